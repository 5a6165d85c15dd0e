#!/usr/bin/env bash
# What cable_sim's output costs beside the step: cable_sim end to end at n = 100 (config/default.yaml with
# 100 links, dt = 1 ms, 20 s simulated), with the default sampling (a CSV row every 0.01 s), with the
# CSV and a rosbag (--bag), and with one row at the start and one at the end only (--sample 20: the steps
# alone, plus the start-up), run in turn, round after round, so that a drift of the shared machine's
# speed touches every variant alike. Figures: the median over the rounds of each run's CPU time (user +
# system, /usr/bin/time) per simulated millisecond, and the output's share: (run - steps alone) / steps alone.
#   bash bench/cable_sim_output.sh [ROUNDS] [BASELINE_CABLE_SIM]
# BASELINE_CABLE_SIM: another cable_sim (e.g. one built from an earlier commit) timed at the default
# sampling in the same rounds. Needs a build (scripts/run.sh or scripts/test.sh).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../scripts/common.sh"
rounds="${1:-7}"
baseline="${2:-}"
sim="$WS_DIR/devel/lib/cable_dynamics/cable_sim"
[ -x "$sim" ] || { echo "no $sim: build first (bash scripts/test.sh)" >&2; exit 1; }
duration=20
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
common=(--config "$REPO_DIR/config/default.yaml" --set cable.links=100 --duration "$duration")

# CPU seconds (user + system) of one run.
cpu() { /usr/bin/time -f "%U %S" -o "$out/time" "$@" >/dev/null 2>"$out/err" || { cat "$out/err" >&2; exit 1; }
  awk '{ printf "%.4f\n", $1 + $2 }' "$out/time"; }

declare -A runs
variants=(csv csv_bag steps)
[ -n "$baseline" ] && variants+=(baseline_csv)
for ((r = 1; r <= rounds; ++r)); do
  runs[csv]+="$(cpu "$sim" "${common[@]}" --output "$out/a.csv") "
  runs[csv_bag]+="$(cpu "$sim" "${common[@]}" --output "$out/b.csv" --bag "$out/b.bag") "
  runs[steps]+="$(cpu "$sim" "${common[@]}" --output "$out/c.csv" --sample "$duration") "
  [ -n "$baseline" ] && runs[baseline_csv]+="$(cpu "$baseline" "${common[@]}" --output "$out/d.csv") "
  echo "[bench] round $r of $rounds" >&2
done
[ -n "$baseline" ] && { cmp -s "$out/a.csv" "$out/d.csv" && echo "baseline's CSV: identical bytes" ||
  echo "baseline's CSV: DIFFERS"; }

median() { tr ' ' '\n' | grep . | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
ms=$((duration * 1000))
steps_us=$(echo "${runs[steps]}" | median | awk -v ms=$ms '{ printf "%.1f", 1e6 * $1 / ms }')
printf "cable_sim, n = 100, dt = 1 ms, %d s simulated, %d rounds; CPU us per simulated ms (median; min..max)\n" \
  "$duration" "$rounds"
for v in "${variants[@]}"; do
  sorted=$(echo "${runs[$v]}" | tr ' ' '\n' | grep . | sort -g)
  med=$(echo "${runs[$v]}" | median | awk -v ms=$ms '{ printf "%.1f", 1e6 * $1 / ms }')
  lo=$(echo "$sorted" | head -1 | awk -v ms=$ms '{ printf "%.1f", 1e6 * $1 / ms }')
  hi=$(echo "$sorted" | tail -1 | awk -v ms=$ms '{ printf "%.1f", 1e6 * $1 / ms }')
  share=$(awk -v a="$med" -v s="$steps_us" 'BEGIN { printf "%.2f", (a - s) / s }')
  printf "  %-13s %7s  (%s..%s)   output / steps: %s\n" "$v" "$med" "$lo" "$hi" "$share"
done
echo "  (steps: --sample $duration, two rows; its figure includes the start-up, config and stable-step estimate)"
