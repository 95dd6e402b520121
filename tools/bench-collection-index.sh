#!/usr/bin/env bash
# A generated collection computed as shard stores on a real one-node Slurm
# (tools/slurm-local.sh, examples/cluster/slurm-submit.sh), then made
# readable as one collection in both ways: the collection index
# (slurm-index.sbatch, the examples' last step) and today's merge
# (slurm-merge.sbatch). Markdown tables on stdout, progress on stderr. A
# benchmark: it times and does not grade, but it stops when a result it
# times would be wrong: a map missing from the index, verify finding a
# problem, or a map's GeoJSON from the index differing from the merged
# store's (and, with --reference, from one unsharded ag-run's).
#
# 1. ag-make-collection writes --maps maps; slurm-submit.sh queues --shards
#    shard tasks (ag-run --shard, then ag-store verify of the shard) and the
#    index job. Compute: the array's wall time from submission to its last
#    task's end, and the sum of the tasks' ag-run times from their logs.
# 2. The index job's own time (its log's "collection: N s": ag-store index)
#    and the merge job's on the same shards (ag-store merge and verify), run
#    after it; then ag-store index alone (median of
#    --repeats), verify of the index with and without --shallow, the maps
#    listed, and the file sizes.
# 3. ag-export --format geojson of every map, one process each as a user
#    would script it, from the index and from the merged store; the two
#    folders must be identical.
# 4. --reference: the same maps in one unsharded ag-run --jobs 2, and every
#    map's GeoJSON from the index compared with its export from that run.
#
# Usage: tools/bench-collection-index.sh [--maps N] [--shards S] [--repeats R] [--reference]
#                                        [--build-dir DIR] [--work DIR] [--no-build]
set -euo pipefail
cd "$(dirname "$0")/.."

bench_name=bench-collection-index
bench_help_lines=2,28
source tools/bench-common.sh
maps=600
shards=4
repeats=3
reference=0
while [ $# -gt 0 ]; do
  case "$1" in
    --maps) maps="$2"; shift 2 ;;
    --shards) shards="$2"; shift 2 ;;
    --repeats) repeats="$2"; shift 2 ;;
    --reference) reference=1; shift ;;
    *) bench_option "$@"; shift "$bench_shift" ;;
  esac
done
work_given="$work"
bench_prepare ag-run ag-store ag-inspect ag-export ag-make-collection
export PATH="$bin:$PATH"
here="$PWD"

now() { date +%s.%N; }
since() { awk -v a="$1" -v b="$(now)" 'BEGIN {printf "%.2f", b - a}'; }
mb() { awk -v b="$(stat -c %s "$@" | awk '{s += $1} END {print s}')" 'BEGIN {printf "%.1f", b / 1e6}'; }
fail() {
  say "$*"
  exit 1
}

# --- the cluster ---------------------------------------------------------------
slurm="$work/slurm"
rm -rf "$slurm"
status=0
start_out=$(tools/slurm-local.sh start "$slurm" --stop-with $$) || status=$?
[ "$status" = 0 ] || fail "tools/slurm-local.sh could not start a cluster (exit $status)"
eval "$start_out"
cleanup() {
  tools/slurm-local.sh stop "$slurm" >/dev/null 2>&1 || true
  if [ -z "$work_given" ]; then rm -rf "$work"; fi
}
trap cleanup EXIT

# The maps an ag-inspect listing names (lines "map artifacts source").
listed_maps() { ag-inspect --store "$1" | awk 'NR > 1 && NF == 3 && $2 ~ /^[0-9]+$/ {print $1}'; }
# Waits until squeue lists none of the jobs given.
wait_for() {
  while [ -n "$(squeue -h -j "$(
    IFS=,
    echo "$*"
  )" 2>/dev/null)" ]; do sleep 0.5; done
}
# The state of a finished job from the job completion log ("COMPLETED").
job_state() { grep "JobId=$1 " "$slurm/jobcomp.log" | tail -n 1 | sed 's/.*JobState=\([A-Z_]*\).*/\1/'; }

echo "### Collection index against merge, $(date -u +%Y-%m-%d), $(nproc) cores, $(uname -m)"
echo
echo "$maps generated maps (ag-make-collection), $shards shard tasks on a one-node Slurm" \
  "(tools/slurm-local.sh); load average before: $(cut -d' ' -f1-3 /proc/loadavg)."
echo

# --- 1. compute ----------------------------------------------------------------
if [ ! -f "$work/maps.done" ]; then
  say "writing $maps maps"
  ag-make-collection --count "$maps" "$work/maps" >&2
  touch "$work/maps.done"
fi
stores="$work/stores"
rm -rf "$stores"
say "queueing $shards shard tasks and the index job"
submitted_at=$(now)
line=$(examples/cluster/slurm-submit.sh "$work/maps" "$stores" "$shards" | tail -n 1)
read -r _ array _ index_job <<<"$line"
wait_for "$array"
compute_wall=$(since "$submitted_at")
wait_for "$index_job"
index_log="$stores/logs/index-job$index_job.out"
[ "$(job_state "$index_job")" = COMPLETED ] || fail "the index job did not complete: $(cat "$index_log")"
index_step=$(sed -n 's/^collection: \([0-9.]*\) s$/\1/p' "$index_log")
runs=$(cat "$stores"/logs/shard-*.out | sed -n 's/.* in \([0-9.]*\) s (.*/\1/p' |
  awk '{s += $1} END {printf "%.1f", s}')
checked=$(cat "$stores"/logs/shard-*.out | grep -c ': no problems$' || true)
[ "$checked" = "$shards" ] || fail "only $checked of $shards shard tasks verified their store"

# --- 2. the collection steps -----------------------------------------------------
index="$stores/collection.db"
listed=$(listed_maps "$index" | wc -l)
[ "$listed" = "$maps" ] || fail "the index lists $listed maps, not $maps"
say "merge job on the same shards"
merge_dir="$work/stores-merge"
rm -rf "$merge_dir"
mkdir -p "$merge_dir/logs"
for shard in "$stores"/shard-*.db; do ln -s "$shard" "$merge_dir/$(basename "$shard")"; done
merge_job=$(sbatch --parsable --output="$merge_dir/logs/merge.out" \
  examples/cluster/slurm-merge.sbatch "$merge_dir")
merge_job="${merge_job%%;*}"
wait_for "$merge_job"
[ "$(job_state "$merge_job")" = COMPLETED ] || fail "the merge job failed: $(cat "$merge_dir/logs/merge.out")"
merge_step=$(sed -n 's/^collection: \([0-9.]*\) s$/\1/p' "$merge_dir/logs/merge.out")
merged="$merge_dir/collection.db"

times=()
for round in $(seq "$repeats"); do
  start=$(now)
  ag-store index --out "$work/again.db" "$stores"/shard-*.db >/dev/null
  times+=("$(since "$start")")
done
index_alone=$(printf '%s\n' "${times[@]}" | median)
start=$(now)
ag-store verify --shallow --store "$index" >/dev/null || fail "verify --shallow found problems"
shallow=$(since "$start")
start=$(now)
ag-store verify --store "$index" >/dev/null || fail "verify found problems"
full=$(since "$start")

# --- 3. exports ------------------------------------------------------------------
export_all() {  # STORE DIR: every map's GeoJSON into DIR; prints the seconds
  local store="$1" dir="$2" start name
  rm -rf "$dir"
  mkdir -p "$dir"
  start=$(now)
  while read -r name; do
    ag-export --store "$store" --map "$name" --format geojson --out "$dir/${name//\//_}.geojson" \
      >/dev/null  # its "wrote FILE" line
  done < <(listed_maps "$store")
  since "$start"
}
say "exporting every map from the index"
export_index=$(export_all "$index" "$work/export-index")
say "exporting every map from the merged store"
export_merged=$(export_all "$merged" "$work/export-merged")
diff -rq "$work/export-index" "$work/export-merged" >&2 || fail "exports differ"

echo "| step | collection index | ag-store merge |"
echo "|---|---:|---:|"
echo "| compute: $shards shard tasks (submission to the last task's end) | $compute_wall s | same |"
echo "| compute: the tasks' ag-run times, summed | $runs s | same |"
echo "| the collection job (its log's \`collection: N s\`) | $index_step s | $merge_step s |"
echo "| ag-store index alone (median of $repeats) | $index_alone s | |"
echo "| ag-store verify --shallow / verify of the result | $shallow s / $full s | (in the job) |"
echo "| ag-export --format geojson of all $maps maps | $export_index s | $export_merged s |"
echo "| file | $(mb "$index") MB (shards: $(mb "$stores"/shard-*.db) MB) | $(mb "$merged") MB |"
echo
echo "Maps listed by the index: $listed; every shard verified in its task; exports of the index" \
  "and of the merged store identical. The collection job's share of the compute wall:" \
  "$(awk -v i="$index_step" -v c="$compute_wall" 'BEGIN {printf "%.2f", 100 * i / c}') %" \
  "(merge: $(awk -v i="$merge_step" -v c="$compute_wall" 'BEGIN {printf "%.2f", 100 * i / c}') %)."

# --- 4. reference ----------------------------------------------------------------
if [ "$reference" = 1 ]; then
  say "one unsharded ag-run --jobs 2"
  start=$(now)
  ag-run --store "$work/reference.db" --jobs 2 "$work/maps" >/dev/null 2>&1 || [ $? -eq 1 ]
  unsharded=$(since "$start")
  export_reference=$(export_all "$work/reference.db" "$work/export-reference")
  diff -rq "$work/export-index" "$work/export-reference" >&2 ||
    fail "exports from the index differ from the unsharded run's"
  echo
  echo "One unsharded \`ag-run --jobs 2\` of the same maps: $unsharded s; every map's GeoJSON from" \
    "the index is byte-identical to its export from that run (export of all: $export_reference s)."
fi
echo
echo "Load average after: $(cut -d' ' -f1-3 /proc/loadavg)."
cd "$here"
