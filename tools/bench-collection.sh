#!/usr/bin/env bash
# Throughput of ag-run on a synthetic collection (ag-make-collection: random
# office floors, 0.05 m/px), printed as Markdown tables on stdout; progress on
# stderr. A benchmark: it checks nothing, but prints the ratios that
# docs/performance.md sets targets for (warm <= 1/20 cold, jobs 2 >= 1.7x jobs 1).
#
# 1. Cold and warm runs of the whole collection with --jobs 1 and --jobs 2.
#    Cold runs go into a new store each, --cold-runs times per setting with
#    the settings alternating (so that drift hits both alike); warm runs
#    repeat --warm-runs times on the last cold store. Medians are shown, and
#    the store size after a cold run.
# 2. Store growth: one store filled in batches of 100 maps (--jobs 2); the
#    time per map of each batch, and of a warm re-run of the first batch, as
#    the store grows. Flat means that no step scans the whole store.
#
# Usage: tools/bench-collection.sh [--maps N] [--cold-runs C] [--warm-runs R] [--build-dir DIR]
#                                  [--work DIR] [--no-build]
set -euo pipefail
cd "$(dirname "$0")/.."

bench_name=bench-collection
bench_help_lines=2,18
source tools/bench-common.sh
maps=1000
cold_runs=2
warm_runs=3
while [ $# -gt 0 ]; do
  case "$1" in
    --maps) maps="$2"; shift 2 ;;
    --cold-runs) cold_runs="$2"; shift 2 ;;
    --warm-runs) warm_runs="$2"; shift 2 ;;
    *) bench_option "$@"; shift "$bench_shift" ;;
  esac
done
bench_prepare ag-run ag-make-collection

now() { date +%s.%N; }
# Seconds taken by one ag-run (stdout and stderr dropped; a failure stops the bench).
timed_run() {
  local start end
  start=$(now)
  "$bin/ag-run" "$@" >/dev/null 2>"$work/last.err" || {
    say "ag-run $* failed:"; cat "$work/last.err" >&2; exit 1; }
  end=$(now)
  awk -v a="$start" -v b="$end" 'BEGIN {printf "%.3f\n", b - a}'
}
store_mb() { du -cm "$1" "$1"-wal 2>/dev/null | tail -1 | cut -f1; }

say "writing $maps maps to $work/maps"
"$bin/ag-make-collection" --count "$maps" "$work/maps" >&2
collection_mb=$(du -sm "$work/maps" | cut -f1)

declare -A cold_times warm size
for round in $(seq "$cold_runs"); do
  for jobs in 1 2; do
    store="$work/jobs$jobs.db"
    rm -f "$store" "$store"-wal "$store"-shm
    say "cold run $round of $cold_runs, --jobs $jobs"
    cold_times[$jobs]+="$(timed_run --store "$store" --jobs "$jobs" "$work/maps") "
    size[$jobs]=$(store_mb "$store")
  done
done
declare -A cold
for jobs in 1 2; do
  cold[$jobs]=$(printf '%s\n' ${cold_times[$jobs]} | median)
  store="$work/jobs$jobs.db"
  times=()
  for _ in $(seq "$warm_runs"); do
    times+=("$(timed_run --store "$store" --jobs "$jobs" "$work/maps")")
  done
  warm[$jobs]=$(printf '%s\n' "${times[@]}" | median)
  say "  --jobs $jobs: cold ${cold_times[$jobs]}s, warm ${warm[$jobs]} s, store ${size[$jobs]} MB"
done

echo "### ag-run on $maps synthetic maps ($collection_mb MB of PNG), $(date -u +%Y-%m-%d), $(nproc) cores"
echo
echo "| jobs | cold s (median of $cold_runs) | cold maps/s | warm s (median of $warm_runs) | warm maps/s | warm / cold | store MB |"
echo "|---:|---:|---:|---:|---:|---:|---:|"
for jobs in 1 2; do
  awk -v j="$jobs" -v c="${cold[$jobs]}" -v w="${warm[$jobs]}" -v n="$maps" -v s="${size[$jobs]}" \
    'BEGIN {printf "| %d | %.1f | %.1f | %.2f | %.0f | 1/%.0f | %d |\n", j, c, n/c, w, n/w, c/w, s}'
done
echo
awk -v c1="${cold[1]}" -v c2="${cold[2]}" -v t1="${cold_times[1]}" -v t2="${cold_times[2]}" \
  'BEGIN {printf "Cold speed-up of --jobs 2 over --jobs 1: %.2fx (cold runs, s: jobs 1: %s; jobs 2: %s).\n", c1/c2, t1, t2}'
echo

# Store growth: batches of 100 maps, one subfolder each.
growth="$work/growth.db"
echo "### Time per map as the store grows (--jobs 2, batches of 100 maps)"
echo
echo "| batch | maps in store before | store MB before | cold ms/map | warm ms/map (batch 000) |"
echo "|---:|---:|---:|---:|---:|"
done_maps=0
for folder in "$work"/maps/*/; do
  name=$(basename "$folder")
  count=$(find "$folder" -name '*.png' | wc -l)
  before_mb=0
  [ -f "$growth" ] && before_mb=$(store_mb "$growth")
  seconds=$(timed_run --store "$growth" --jobs 2 "$folder")
  warm_seconds=$(timed_run --store "$growth" --jobs 2 "$work/maps/000")
  first_count=$(find "$work/maps/000" -name '*.png' | wc -l)
  awk -v b="$name" -v d="$done_maps" -v m="$before_mb" -v s="$seconds" -v n="$count" \
    -v w="$warm_seconds" -v f="$first_count" \
    'BEGIN {printf "| %s | %d | %d | %.1f | %.2f |\n", b, d, m, 1000*s/n, 1000*w/f}'
  done_maps=$((done_maps + count))
  say "  batch $name done"
done
