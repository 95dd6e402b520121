#!/usr/bin/env bash
# Inputs for planning a large collection on a cluster (docs/performance.md,
# "Planning 100,000 maps"), printed as Markdown tables on stdout; progress on
# stderr. A benchmark: it checks nothing.
#
# 1. Shards: ag-make-collection writes STORES x MAPS synthetic maps; ag-run
#    --shard s/STORES --jobs 2 computes each shard into its own store, as the
#    cluster examples do. Per shard: wall time, CPU time (user + system) per
#    map, and store MB per map.
# 2. Merge: `ag-store merge` of the first k shard stores into a new store, for
#    k = 1, 2, 5, STORES (each --repeats times, median), to show how it grows.
# 3. Verify: `ag-store verify` of the merged store of all shards (--repeats
#    times, median).
# 4. Real maps: the same cold cost and store size on the 36 maps of
#    ../shared/data (areagraph/input and maoris/RobotMap/Maps), when present.
#
# The disk needs about 2.2 x STORES x MAPS x 0.95 MB (10 x 1000: ~21 GB).
#
# Usage: tools/bench-cluster-plan.sh [--stores N] [--maps-per-store M] [--repeats R]
#                                    [--build-dir DIR] [--work DIR] [--no-build]
set -euo pipefail
cd "$(dirname "$0")/.."

bench_name=bench-cluster-plan
bench_help_lines=2,21
source tools/bench-common.sh
stores=10
per_store=1000
repeats=3
while [ $# -gt 0 ]; do
  case "$1" in
    --stores) stores="$2"; shift 2 ;;
    --maps-per-store) per_store="$2"; shift 2 ;;
    --repeats) repeats="$2"; shift 2 ;;
    *) bench_option "$@"; shift "$bench_shift" ;;
  esac
done
bench_prepare ag-run ag-store ag-make-collection

# Bytes of a store file and its write-ahead log.
bytes() {
  local total=0 file
  for file in "$1" "$1"-wal; do
    if [ -f "$file" ]; then total=$((total + $(stat -c %s "$file"))); fi
  done
  echo "$total"
}
# Runs a command; prints "wall user system" in seconds. Exit 1 of ag-run
# (some maps failed, recorded) is accepted; anything else stops the bench.
measure() {
  local status=0
  /usr/bin/time -f "%e %U %S" -o "$work/time.txt" "$@" >"$work/last.out" 2>"$work/last.err" ||
    status=$?
  if [ "$status" -gt 1 ]; then
    say "$* failed ($status):"
    cat "$work/last.err" >&2
    exit 1
  fi
  tail -n 1 "$work/time.txt"
}
# Heads of the merge stage in a store: the maps it holds a graph for.
graphs() { sqlite3 "$1" "SELECT count(*) FROM heads WHERE stage = 'merge'"; }

total=$((stores * per_store))
echo "### Cluster planning inputs, $(date -u +%Y-%m-%d), $(nproc) cores, $(uname -m)"
echo

# --- 1. shards ---------------------------------------------------------------
if [ ! -f "$work/maps.done" ]; then
  say "writing $total maps to $work/maps"
  "$bin/ag-make-collection" --count "$total" "$work/maps" >&2
  touch "$work/maps.done"
fi
echo "#### $stores shard stores of about $per_store synthetic maps (ag-run --shard s/$stores --jobs 2)"
echo
echo "| shard | maps | wall s | CPU ms/map | MB/map |"
echo "|---:|---:|---:|---:|---:|"
cpu_per_map=()
mb_per_map=()
for shard in $(seq 0 $((stores - 1))); do
  store="$work/shard-$shard.db"
  if [ ! -f "$store.time" ]; then  # a --work folder keeps the shards already done
    rm -f "$store" "$store"-wal "$store"-shm
    say "shard $shard of $stores"
    read -r wall user system < <(measure "$bin/ag-run" --store "$store" --shard "$shard/$stores" \
      --jobs 2 "$work/maps")
    echo "$wall $user $system" >"$store.time"
  fi
  read -r wall user system <"$store.time"
  maps=$(graphs "$store")
  size=$(bytes "$store")
  cpu=$(awk -v u="$user" -v s="$system" -v n="$maps" 'BEGIN {printf "%.1f", 1000 * (u + s) / n}')
  mb=$(awk -v b="$size" -v n="$maps" 'BEGIN {printf "%.3f", b / n / 1e6}')
  cpu_per_map+=("$cpu")
  mb_per_map+=("$mb")
  echo "| $shard | $maps | $wall | $cpu | $mb |"
done
echo
echo "Median CPU time per map: $(printf '%s\n' "${cpu_per_map[@]}" | median) ms;" \
  "median store size per map: $(printf '%s\n' "${mb_per_map[@]}" | median) MB."
echo

# --- 2. merge ----------------------------------------------------------------
echo "#### ag-store merge of k shard stores into a new store (median of $repeats)"
echo
echo "| k stores | maps | store GB | merge s | s per 1000 maps | MB/s |"
echo "|---:|---:|---:|---:|---:|---:|"
merged="$work/merged.db"
for k in $(printf '%s\n' 1 2 5 "$stores" | sort -nu); do
  [ "$k" -le "$stores" ] || continue
  inputs=()
  for shard in $(seq 0 $((k - 1))); do inputs+=("$work/shard-$shard.db"); done
  times=()
  for round in $(seq "$repeats"); do
    rm -f "$merged" "$merged"-wal "$merged"-shm
    say "merge of $k stores, round $round of $repeats"
    read -r wall _ _ < <(measure "$bin/ag-store" merge "$merged" "${inputs[@]}")
    times+=("$wall")
  done
  seconds=$(printf '%s\n' "${times[@]}" | median)
  maps=$(graphs "$merged")
  size=$(bytes "$merged")
  awk -v k="$k" -v m="$maps" -v b="$size" -v s="$seconds" -v all="${times[*]}" \
    'BEGIN {printf "| %d | %d | %.2f | %.1f | %.2f | %.0f |\n", k, m, b / 1e9, s, 1000 * s / m, b / 1e6 / s}'
  say "  merge of $k stores: ${times[*]} s"
  if [ "$k" != "$stores" ]; then rm -f "$merged" "$merged"-wal "$merged"-shm; fi
done
echo

# --- 3. verify ---------------------------------------------------------------
times=()
for round in $(seq "$repeats"); do
  say "verify, round $round of $repeats"
  read -r wall _ _ < <(measure "$bin/ag-store" verify --store "$merged")
  times+=("$wall")
done
seconds=$(printf '%s\n' "${times[@]}" | median)
size=$(bytes "$merged")
awk -v s="$seconds" -v b="$size" -v m="$(graphs "$merged")" -v all="${times[*]}" \
  'BEGIN {printf "ag-store verify of the merged store (%d maps, %.2f GB): %.1f s median (%s), %.0f MB/s, %.2f s per 1000 maps.\n", m, b / 1e9, s, all, b / 1e6 / s, 1000 * s / m}'
echo
rm -f "$merged" "$merged"-wal "$merged"-shm

# --- 4. real maps ------------------------------------------------------------
data=../shared/data
if [ -d "$data/areagraph/input" ] && [ -d "$data/maoris/RobotMap/Maps" ]; then
  real="$work/real"
  mkdir -p "$real/maps/areagraph" "$real/maps/RobotMap"
  cp "$data"/areagraph/input/*.png "$real/maps/areagraph/"
  cp "$data"/maoris/RobotMap/Maps/*.png "$real/maps/RobotMap/"
  echo "#### The 36 real maps (areagraph/input, RobotMap), cold, --jobs 2 (median of $repeats)"
  echo
  walls=()
  cpus=()
  for round in $(seq "$repeats"); do
    rm -f "$real/store.db" "$real/store.db"-wal "$real/store.db"-shm
    say "real maps, round $round of $repeats"
    read -r wall user system < <(measure "$bin/ag-run" --store "$real/store.db" --jobs 2 \
      "$real/maps")
    walls+=("$wall")
    cpus+=("$(awk -v u="$user" -v s="$system" 'BEGIN {print u + s}')")
  done
  maps=$(graphs "$real/store.db")
  size=$(bytes "$real/store.db")
  awk -v w="$(printf '%s\n' "${walls[@]}" | median)" -v c="$(printf '%s\n' "${cpus[@]}" | median)" \
    -v n="$maps" -v b="$size" \
    'BEGIN {printf "%d maps: wall %.1f s, CPU %.0f ms/map, store %.2f MB/map.\n", n, w, 1000 * c / n, b / n / 1e6}'
  echo
fi
