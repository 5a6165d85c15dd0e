#!/usr/bin/env bash
# The speed benchmark in one command: installs what it needs (Debian packages), builds bench/ into
# bench/build/, runs cable_bench and prints its tables (kept in bench/build/results.txt too).
# Arguments go to cable_bench, e.g.  bash bench/run.sh --sizes=10,30,100 --reps=3
# Exit status: cable_bench's (non-zero when a system failed the energy check).
set -euo pipefail

start=$(date +%s)
# Debian's compilers and cmake first: a pyenv or venv python3 shadowing /usr/bin is no business of ours.
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:$PATH"
BENCH_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
BUILD_DIR="$BENCH_DIR/build"

# shellcheck source=bench/packages.sh
source "$BENCH_DIR/packages.sh"
install_missing_packages bench cmake make g++ libeigen3-dev libyaml-cpp-dev libmujoco-dev libdart-dev libsimbody-dev \
  liborocos-kdl-dev

echo "[bench] building into $BUILD_DIR"
mkdir -p "$BUILD_DIR"
cmake -S "$BENCH_DIR" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release >"$BUILD_DIR/configure.log" 2>&1 ||
  { cat "$BUILD_DIR/configure.log"; exit 1; }
grep -E "left out|not found" "$BUILD_DIR/configure.log" || true
cmake --build "$BUILD_DIR" -j"$(nproc)"

echo "[bench] running (progress on stderr; a full run takes a few minutes)"
cd "$BUILD_DIR"  # anything an engine writes to its working directory stays in the build tree
set +e
./cable_bench "$@" | tee "$BUILD_DIR/results.txt"
status=${PIPESTATUS[0]}
./fluid_step | tee -a "$BUILD_DIR/results.txt"  # the project alone, with full fluid forces
./fluid_step_baseline 100,1000 | tee -a "$BUILD_DIR/results.txt"  # the same without the AVX2/FMA copies
./winch_step | tee -a "$BUILD_DIR/results.txt"  # what the winch adds to a step
./seabed_step | tee -a "$BUILD_DIR/results.txt"  # what the seabed adds to a step
./stiff_step | tee -a "$BUILD_DIR/results.txt"  # issue 15: the stiff presets, RK4 / implicit / DART springs
set -e
echo "[bench] bench/run.sh total wall time: $(($(date +%s) - start)) s (packages, build and benchmark)"
exit "$status"
