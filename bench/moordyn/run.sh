#!/usr/bin/env bash
# Issue 24, item 1: cable_dynamics side by side with MoorDyn, one table (moordyn_bench.cpp says what it
# measures). MoorDyn is not part of this repository: build and install it from its public repository
# (github.com/FloatingArrayDesign/MoorDyn, v2.7.1 here) and point MOORDYN_DIR at its source tree (its
# install in install/, its validation references in tests/Mooring/) or at its install prefix (no OrcaFlex
# series then). Without MOORDYN_DIR this prints a line and exits 0: nothing in CI needs MoorDyn.
#   MOORDYN_DIR=/path/to/MoorDyn bash bench/moordyn/run.sh [repetitions, default 5]
# MDB_ONLY=<line> runs one line of the table; MDB_ONLY=grounded only the grounded catenary's statics
# (moordyn_grounded.cpp), which otherwise follows the whole table.
# Builds under nice into bench/moordyn/build/ (-j1: the machine is shared; BENCH_JOBS to change).
set -euo pipefail
if [[ -z "${MOORDYN_DIR:-}" ]]; then
  echo "MoorDyn: skipped (set MOORDYN_DIR)"
  exit 0
fi
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:$PATH"  # Debian's cmake and compilers before any pyenv shim
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
BUILD="$HERE/build"
mkdir -p "$BUILD"
cmake -S "$HERE" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DMOORDYN_DIR="$MOORDYN_DIR" >"$BUILD/configure.log" 2>&1 ||
  { cat "$BUILD/configure.log"; exit 1; }
nice -n 10 cmake --build "$BUILD" -j"${BENCH_JOBS:-1}" >"$BUILD/build.log" 2>&1 || { tail -40 "$BUILD/build.log"; exit 1; }
# MoorDyn writes next to its input files: run on copies in the build tree.
rm -rf "$BUILD/lines" && cp -r "$HERE/lines" "$BUILD/lines"
LIB="$(dirname "$(find "$MOORDYN_DIR" -name 'libmoordyn.so*' -print -quit)")"
cd "$BUILD"
echo "[moordyn bench] $(date -u '+%F %T UTC'); uptime: $(uptime)" | tee "$BUILD/results.txt"
if [[ "${MDB_ONLY:-}" != grounded ]]; then
  LD_LIBRARY_PATH="$LIB:${LD_LIBRARY_PATH:-}" ./moordyn_bench "$BUILD/lines" "${1:-5}" "$MOORDYN_DIR" | tee -a "$BUILD/results.txt"
fi
# The grounded elastic catenary (moordyn_grounded.cpp): after the whole table, or alone with MDB_ONLY=grounded.
if [[ -z "${MDB_ONLY:-}" || "${MDB_ONLY}" == grounded ]]; then
  LD_LIBRARY_PATH="$LIB:${LD_LIBRARY_PATH:-}" ./moordyn_grounded | tee -a "$BUILD/results.txt"
fi
