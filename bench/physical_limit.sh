#!/usr/bin/env bash
# Issue 24, the physical limit: each integrator's floating-point work and data per link and step against
# this machine's measured peak and bandwidth (docs/performance.md, "The physical limit (issue 24)").
# Prints figures and tables; judges nothing (not a test, not run by CI). About 3 minutes on the 2-core VM
# (valgrind's runs most of it).
#   bash bench/physical_limit.sh [path/to/cable_sim]     # default: the workspace's (scripts/common.sh)
# Needs: g++, cmake, valgrind, binutils (objdump), python3, perf (optional: the time by function), and a
# Release build of the package's cable_sim.
set -euo pipefail
export PATH=/usr/bin:$PATH
HERE=$(cd "$(dirname "$0")" && pwd)
REPO=$(dirname "$HERE")
source "$REPO/scripts/common.sh"
CABLE_SIM=${1:-$WS_DIR/devel/lib/cable_dynamics/cable_sim}
[ -x "$CABLE_SIM" ] || { echo "no $CABLE_SIM: build first (bash scripts/test.sh) or give a cable_sim" >&2; exit 1; }
OUT=$HERE/build/physical_limit
mkdir -p "$OUT"

# machine_peak: built alone with the bench's flags (bench/CMakeLists.txt: -O2, no errno, no trapping math);
# its kernels choose AVX2/FMA themselves, as the core's hot path does at run time. link_bytes: built by
# bench/CMakeLists.txt against the core of this checkout.
g++ -std=c++17 -O2 -DNDEBUG -fno-math-errno -fno-trapping-math -o "$OUT/machine_peak" "$HERE/src/machine_peak.cpp"
[ -f "$HERE/build/CMakeCache.txt" ] || cmake -S "$HERE" -B "$HERE/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$HERE/build" --target link_bytes -j2 >/dev/null

echo "# $(date -u '+%Y-%m-%d %H:%M UTC'), this checkout at $(git -C "$REPO" rev-parse --short HEAD), cable_sim $CABLE_SIM, load:$(uptime | sed 's/.*load average://')"
echo "# $(lscpu | grep -E '^Model name' | tr -s ' '); $(lscpu | grep -E '^(L1d|L2|L3) cache' | tr -s ' ' | paste -sd ';')"
"$OUT/machine_peak" | tee "$OUT/machine.txt"
python3 "$HERE/physical_limit.py" --cable-sim "$CABLE_SIM" --machine "$OUT/machine.txt" --link-bytes "$HERE/build/link_bytes"
echo "# load after:$(uptime | sed 's/.*load average://')"
