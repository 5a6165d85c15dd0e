#!/usr/bin/env bash
# Behaviour unchanged: runs cable_sim on every config/*.yaml preset for a few seconds with two builds and
# compares their CSVs value by value. A value matches when |new - old| <= TOL * max(1, |old|, column
# scale), the column scale being the largest |value| of that column in the old run (relative where a
# column is large: energies of kJ, tensions of kN; absolute 1e-9 where it is of order one). Prints per
# preset the rows compared, the worst column and its difference; exits non-zero on any mismatch, a
# missing run or a different number of rows or columns.
#
#   bash bench/compare_trajectories.sh OLD_CABLE_SIM NEW_CABLE_SIM [DURATION]
#     OLD_CABLE_SIM  e.g. /work/main_ws/devel/lib/cable_dynamics/cable_sim (a build of the old commit)
#     NEW_CABLE_SIM  e.g. <worktree>_ws/devel/lib/cable_dynamics/cable_sim
#     DURATION       simulated seconds per preset, default 3
#   TOL=1e-9  SAMPLE=0.01 (CSV row interval [s])  CONFIG_DIR=<repo>/config
# Both binaries read the same preset files (this checkout's config/), so only the code differs.
set -euo pipefail
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:$PATH"
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
old_sim="${1:?usage: compare_trajectories.sh OLD_CABLE_SIM NEW_CABLE_SIM [DURATION]}"
new_sim="${2:?usage: compare_trajectories.sh OLD_CABLE_SIM NEW_CABLE_SIM [DURATION]}"
duration="${3:-3}"
TOL="${TOL:-1e-9}"
SAMPLE="${SAMPLE:-0.01}"
CONFIG_DIR="${CONFIG_DIR:-$REPO/config}"
out="$(mktemp -d "${TMPDIR:-/tmp}/compare_trajectories.XXXXXX")"
trap 'rm -rf "$out"' EXIT

failed=0
printf "%-28s %6s %6s  %-26s %11s %11s\n" preset rows cols "worst column" "|new-old|" "allowed"
for config in "$CONFIG_DIR"/*.yaml; do
  name="$(basename "$config" .yaml)"
  for which in old new; do
    sim="$old_sim"; [ "$which" = new ] && sim="$new_sim"
    status=0
    "$sim" --config "$config" --duration "$duration" --sample "$SAMPLE" --output "$out/$name.$which.csv" \
      >"$out/$name.$which.log" 2>&1 || status=$?
    echo "$status" >"$out/$name.$which.status"
  done
  old_status="$(cat "$out/$name.old.status")"; new_status="$(cat "$out/$name.new.status")"
  if [ "$old_status" != "$new_status" ]; then
    echo "$name: exit status old $old_status, new $new_status"; tail -n 3 "$out/$name.new.log"; failed=1; continue
  fi
  if [ ! -s "$out/$name.old.csv" ]; then
    echo "$name: no CSV (exit status $old_status in both): $(tail -n 1 "$out/$name.old.log")"; continue
  fi
  if ! python3 - "$out/$name.old.csv" "$out/$name.new.csv" "$TOL" "$name" <<'PY'
import csv, math, sys
old_path, new_path, tol, name = sys.argv[1], sys.argv[2], float(sys.argv[3]), sys.argv[4]
def read(path):
    with open(path) as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith('#')]
    return rows[0], rows[1:]
oh, orows = read(old_path)
nh, nrows = read(new_path)
if oh != nh or len(orows) != len(nrows):
    print(f"{name}: header or row count differs ({len(oh)}/{len(nh)} columns, {len(orows)}/{len(nrows)} rows)")
    sys.exit(1)
scale = [0.0] * len(oh)
for r in orows:
    for j, v in enumerate(r):
        try:
            scale[j] = max(scale[j], abs(float(v)))
        except ValueError:
            pass
worst, worst_col, worst_allowed, bad = 0.0, "-", 0.0, 0
for o, n in zip(orows, nrows):
    for j, (a, b) in enumerate(zip(o, n)):
        if a == b:  # the same text: equal (an infinite bend radius in both included)
            continue
        try:
            x, y = float(a), float(b)
        except ValueError:
            bad += a != b
            continue
        if math.isnan(x) and math.isnan(y):
            continue
        allowed = tol * max(1.0, scale[j])
        d = abs(x - y)
        if not d <= allowed:
            bad += 1
        if d / allowed > (worst / worst_allowed if worst_allowed else 0.0):
            worst, worst_col, worst_allowed = d, oh[j], allowed
print(f"{name:<28} {len(orows):6d} {len(oh):6d}  {worst_col:<26} {worst:11.3e} {worst_allowed:11.3e}" + (f"  {bad} MISMATCHES" if bad else ""))
sys.exit(1 if bad else 0)
PY
  then
    failed=1
  fi
done
echo
echo "cable_sim, $duration s per preset, a row every $SAMPLE s; tolerance $TOL x max(1, column scale)"
echo "old: $old_sim"
echo "new: $new_sim"
exit "$failed"
