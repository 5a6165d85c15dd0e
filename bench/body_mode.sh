#!/usr/bin/env bash
# What the ROV body (load.mode: body) costs beside the same cable with an attached load and with a free
# point load: config/bluerov2_tether.yaml (100 m tether, the implicit step at 10 ms) through cable_sim,
# the three modes in turn (body attached free body attached free ...), ROUNDS rounds, at each n of SIZES;
# prints per n and mode the median wall time per simulated second of stepping (a run less a 0.01 s run's
# time), and per round the ratios body/attached
# and body/free (median and range: the machine is shared and noisy, and interleaving makes a slow stretch
# hit all three).
#
#   bash bench/body_mode.sh            ROUNDS=7  SIZES="100 1000"  DURATION=60 (simulated seconds a run)
#   CABLE_SIM=path/to/cable_sim        default: the workspace beside the repository (scripts/common.sh)
set -euo pipefail
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:$PATH"
BENCH_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
REPO="$(cd "$BENCH_DIR/.." && pwd)"
CABLE_SIM="${CABLE_SIM:-$(cd "$REPO/.." && pwd)/$(basename "$REPO")_ws/devel/lib/cable_dynamics/cable_sim}"
[ -x "$CABLE_SIM" ] || CABLE_SIM="$(cd "$REPO/.." && pwd)/main_ws/devel/lib/cable_dynamics/cable_sim"
[ -x "$CABLE_SIM" ] || { echo "cable_sim not found: set CABLE_SIM (build with scripts/test.sh first)" >&2; exit 2; }
ROUNDS="${ROUNDS:-7}"
SIZES="${SIZES:-100 1000}"
DURATION="${DURATION:-60}"
CONFIG="$REPO/config/bluerov2_tether.yaml"

wall() {  # mode links duration -> wall seconds of one cable_sim run
  local start end
  start=$(date +%s.%N)
  "$CABLE_SIM" --config "$CONFIG" --output /dev/null --sample 10 --duration "$3" \
    --set "load.mode=$1" --set "cable.links=$2" >/dev/null 2>&1
  end=$(date +%s.%N)
  python3 -c "print($end - $start)"
}

run() {  # mode links -> wall seconds per simulated second of stepping: a run less a 0.01 s run (start-up,
         # the statics of the initial equilibrium, which differ between the modes, and the output are out)
  local long short
  long=$(wall "$1" "$2" "$DURATION")
  short=$(wall "$1" "$2" 0.01)
  python3 -c "print(($long - $short) / $DURATION)"
}

echo "machine: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg); $ROUNDS rounds of $DURATION s simulated"
for n in $SIZES; do
  body=() attached=() free=()
  for ((r = 0; r < ROUNDS; ++r)); do
    body+=("$(run body "$n")"); attached+=("$(run attached "$n")"); free+=("$(run free "$n")")
  done
  python3 - "$n" "${body[*]}" "${attached[*]}" "${free[*]}" <<'PY'
import statistics, sys
n = sys.argv[1]
body, attached, free = ([float(v) for v in a.split()] for a in sys.argv[2:5])
for name, t in (("body", body), ("attached", attached), ("free", free)):
    print(f"n = {n:>5}  {name:<9} median {statistics.median(t) * 1e3:8.2f} ms per simulated s "
          f"(range {min(t) * 1e3:.2f} to {max(t) * 1e3:.2f})")
for name, other in (("body/attached", attached), ("body/free", free)):
    r = [b / o for b, o in zip(body, other)]
    print(f"n = {n:>5}  {name:<13} median {statistics.median(r):.3f} (range {min(r):.3f} to {max(r):.3f})")
PY
done
