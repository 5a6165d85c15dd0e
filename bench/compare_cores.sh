#!/usr/bin/env bash
# Speed of two commits' cores side by side: builds bench/fluid_step (the project's RK4 step with full
# fluid forces, recursive formulation) once from OLD_REF and once from NEW_REF, then runs the two
# binaries in turn, old new old new ..., ROUNDS rounds, each run `fluid_step 10,100,1000`, and prints
# per n the medians of the recursive column [ns per step], the median and range of the per-round
# new/old ratios, and each binary's own range (the spread).
# TARGET=stiff_step measures the stiff presets instead (config/rov_tether.yaml, armoured_umbilical.yaml:
# RK4 at its stable step and the implicit integrator at its recommended one, `stiff_step SIZES BUDGET`),
# in wall seconds per simulated second, one row per preset, n and scheme.
#
# Why interleaved: the machine is shared and noisy (other jobs compile on its 2 cores). Two separate
# bench runs minutes apart measure the load of those minutes as much as the code; alternating the
# binaries makes a slow stretch hit both, and pairing round i of old with round i of new cancels most
# of it in the ratio. The range of those ratios says how far "within noise" reaches.
#
#   bash bench/compare_cores.sh [OLD_REF] [NEW_REF]
#     OLD_REF  default a825ec3 (the last commit before the core's refactor)
#     NEW_REF  default: the working tree as it is (uncommitted edits included); give HEAD to measure
#              a committed state
#   ROUNDS=5 (rounds, each runs both binaries once)  SIZES=10,100,1000  JOBS=2 (build parallelism)
#
# Each ref is exported with `git archive` into a temporary directory (the repository, its worktrees and
# the working tree are not touched; the working tree, when measured, is built out of source into the
# temporary directory), which is removed on exit. Exit status non-zero if a build or a run fails.
set -euo pipefail

start_seconds=$SECONDS
# Debian's compilers and cmake first: a pyenv or venv python3 shadowing /usr/bin is no business of ours.
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:$PATH"
BENCH_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
REPO="$(git -C "$BENCH_DIR" rev-parse --show-toplevel)"

OLD_REF="${1:-a825ec3}"
NEW_REF="${2:-}"
ROUNDS="${ROUNDS:-5}"
SIZES="${SIZES:-10,100,1000}"
JOBS="${JOBS:-2}"
TARGET="${TARGET:-fluid_step}"
BUDGET="${BUDGET:-1.0}"  # stiff_step: wall seconds per cell
case "$TARGET" in fluid_step|stiff_step) ;; *) echo "TARGET is '$TARGET': expected fluid_step or stiff_step" >&2; exit 2 ;; esac
log() { echo "[compare] $*" >&2; }

# --- packages: only what fluid_step needs (no MuJoCo/DART/...: cable_bench is not built) -------------
# shellcheck source=bench/packages.sh
source "$(dirname "${BASH_SOURCE[0]}")/packages.sh"
install_missing_packages compare cmake make g++ libeigen3-dev libyaml-cpp-dev

# --- the two trees ------------------------------------------------------------------------------------
TMP="$(mktemp -d "${TMPDIR:-/tmp}/compare_cores.XXXXXX")"
trap 'rm -rf "$TMP"' EXIT

# export_tree REF DIR: the committed tree of REF in DIR; prints the full commit hash.
export_tree() {
  local commit
  commit="$(git -C "$REPO" rev-parse --verify --quiet "$1^{commit}")" || { log "not a commit: $1"; return 1; }
  mkdir -p "$2"
  git -C "$REPO" archive --format=tar "$commit" | tar -x -C "$2" || { log "export of $1 failed"; return 1; }
  echo "$commit"
}

old_commit="$(export_tree "$OLD_REF" "$TMP/old")"
old_src="$TMP/old"
if [ -n "$NEW_REF" ]; then
  new_commit="$(export_tree "$NEW_REF" "$TMP/new")"
  new_src="$TMP/new"
  new_label="$NEW_REF = $new_commit"
else
  new_commit="$(git -C "$REPO" rev-parse HEAD)"
  new_src="$REPO"
  new_label="working tree on $new_commit"
  [ -z "$(git -C "$REPO" status --porcelain --untracked-files=no)" ] || new_label+=" (with uncommitted changes)"
fi

# build SRC_TREE NAME: bench/$TARGET of SRC_TREE, built in $TMP/build-NAME (only that target).
build() {
  local dir="$TMP/build-$2"
  log "building $2 $TARGET ($1)"
  if ! { cmake -S "$1/bench" -B "$dir" -DCMAKE_BUILD_TYPE=Release &&
         cmake --build "$dir" --target "$TARGET" -j"$JOBS"; } >"$TMP/build-$2.log" 2>&1; then
    tail -n 40 "$TMP/build-$2.log" >&2
    log "build of $2 failed"
    return 1
  fi
}
build "$old_src" old
build "$new_src" new

# --- the runs, interleaved ----------------------------------------------------------------------------
# recursive_column FILE: "n ns" per table row of a fluid_step output, the column found by its header
# (the paper column reads '-' where it is skipped, n > 100).
recursive_column() {
  awk '$1 == "n" { col = 0; for (i = 1; i <= NF; ++i) if ($i == "recursive") col = i; next }
       col && $1 ~ /^[0-9]+$/ && $col ~ /^[0-9.]+$/ { print $1, $col }' "$1"
}
# stiff_cells FILE: "preset:n:scheme seconds" for the RK4 and the implicit cells of a stiff_step output
# (the first two "<number> s" cells of each row: rk4 at its stable step, implicit on the preset).
stiff_cells() {
  awk '/\(config\// { preset = $1; next }
       preset != "" && $1 ~ /^[0-9]+$/ {
         c = 0
         for (i = 2; i < NF; ++i) if ($(i + 1) == "s" && $i ~ /^[0-9.e+-]+$/) { ++c; if (c <= 2) print preset ":" $1 ":" (c == 1 ? "rk4" : "implicit"), $i }
       }' "$1"
}
measure() {  # measure BINARY OUT: runs it, prints "key value" lines
  if [ "$TARGET" = fluid_step ]; then
    "$1" "$SIZES" >"$2" 2>&1 && recursive_column "$2"
  else
    "$1" "$SIZES" "$BUDGET" >"$2" 2>&1 && stiff_cells "$2"
  fi
}

load_before="$(cut -d' ' -f1-3 /proc/loadavg)"
: >"$TMP/values"
for ((round = 1; round <= ROUNDS; ++round)); do
  for which in old new; do
    log "round $round/$ROUNDS: $which"
    out="$TMP/run-$which-$round.txt"
    if ! measure "$TMP/build-$which/$TARGET" "$out" >"$TMP/parsed"; then
      cat "$out" >&2
      log "$TARGET ($which, round $round) failed"
      exit 1
    fi
    sed "s/^/$which $round /" "$TMP/parsed" >>"$TMP/values"
  done
done
load_after="$(cut -d' ' -f1-3 /proc/loadavg)"

# Every row must have a value in every run.
keys="$(awk '{ print $3 }' "$TMP/values" | awk '!seen[$0]++' | paste -sd, -)"
[ -n "$keys" ] || { log "no values parsed"; exit 1; }
for n in ${keys//,/ }; do
  for which in old new; do
    count="$(awk -v w="$which" -v n="$n" '$1 == w && $3 == n' "$TMP/values" | wc -l)"
    [ "$count" -eq "$ROUNDS" ] || { log "$n: $count of $ROUNDS $which values parsed"; exit 1; }
  done
done

# --- the table -----------------------------------------------------------------------------------------
echo
if [ "$TARGET" = fluid_step ]; then
  echo "fluid_step, recursive formulation, RK4 dt = 1 ms, full fluid forces: wall time per step [ns]"
else
  echo "stiff_step: wall seconds per simulated second (rk4 at its stable step, implicit at its recommended one), rows preset:n:scheme"
fi
echo "old: $OLD_REF = $old_commit"
echo "new: $new_label"
echo "$ROUNDS rounds, old and new interleaved (old new old new ...); each value is one run's median of 5"
echo "nproc: $(nproc); load average (1, 5, 15 min) before: $load_before, after: $load_after"
echo
awk -v sizes="$keys" -v rounds="$ROUNDS" -v fmt="$([ "$TARGET" = fluid_step ] && echo %.0f || echo %.4g)" '
  function sort(a, k,   i, j, t) { for (i = 2; i <= k; ++i) for (j = i; j > 1 && a[j - 1] > a[j]; --j) { t = a[j]; a[j] = a[j - 1]; a[j - 1] = t } }
  function median(a, k) { return k % 2 ? a[(k + 1) / 2] : (a[k / 2] + a[k / 2 + 1]) / 2 }
  # stats(a, k): "median  min-max  (max-min)/median" of the k values in a (sorted in place).
  function stats(a, k, fmt) { sort(a, k); return sprintf(fmt " %s %s", median(a, k), sprintf(fmt "-" fmt, a[1], a[k]), sprintf("%.0f%%", 100 * (a[k] - a[1]) / median(a, k))) }
  { v[$1, $2, $3] = $4 }
  END {
    printf "%-5s | %9s %15s %6s | %9s %15s %6s | %7s %11s %6s\n", "n", "old", "old min-max", "spread", "new", "new min-max", "spread", "new/old", "min-max", "spread"
    k = split(sizes, n, ",")
    for (s = 1; s <= k; ++s) {
      for (r = 1; r <= rounds; ++r) { o[r] = v["old", r, n[s]]; w[r] = v["new", r, n[s]]; q[r] = w[r] / o[r] }
      split(stats(o, rounds, fmt), so, " "); split(stats(w, rounds, fmt), sw, " "); split(stats(q, rounds, "%.3f"), sq, " ")
      printf "%-5s | %9s %15s %6s | %9s %15s %6s | %7s %11s %6s\n", n[s], so[1], so[2], so[3], sw[1], sw[2], sw[3], sq[1], sq[2], sq[3]
    }
    print ""
    print "old/new [ns] and new/old per round:"
    for (s = 1; s <= k; ++s) {
      line = sprintf("  n = %-5s", n[s])
      for (r = 1; r <= rounds; ++r) line = line sprintf("  " fmt "/" fmt " %.3f", v["old", r, n[s]], v["new", r, n[s]], v["new", r, n[s]] / v["old", r, n[s]])
      print line
    }
  }' "$TMP/values"
echo
echo "medians over the rounds; new/old: median and range of the per-round ratios (round i of each);"
echo "spread = (max - min) / median. Total wall time: $((SECONDS - start_seconds)) s (builds and runs)."
