#!/usr/bin/env bash
# Times every stage on the 16 Area Graph input maps against the speed floor
# (ag-bench-floor: decoding the image plus the CGAL Delaunay triangulation of
# the obstacle cells next to free space) and prints a Markdown table on
# stdout; progress goes to stderr. A benchmark: it checks nothing.
#
# Each map runs --runs times, each time in a new, empty store: ag-import, then
# ag-pipeline (or, while that is not built, the stage executables one by one;
# missing ones are skipped with a note). Per map the table shows medians:
#   import     wall time of the ag-import process (the store records no
#              compute time for the import itself),
#   clean..merge  compute time inside the stage, as the store records it
#              (ag-inspect's ms column),
#   stages     their sum (import's wall included),
#   total      wall time of all processes of the run: start-up, store reads
#              and writes included,
#   total/floor, and the peak resident memory of any process of the run.
# The floor is the median of --floor-repeat runs inside one process.
# More tables (tools/bench-speed-series.sh), each against the floor of the
# same maps in the same run, with ag-run --jobs 1 from a new store (start-up
# included, wall and CPU time): "runs", the 16 maps one by one; "scale",
# lab_a tiled N x N into one connected map (--tiles, default 1 2 4 6 8),
# also against the floor run with glibc's huge-page tunable, as ag-run runs
# maps over 5 Mpx;
# "clutter", rooms of N x N px with 1 % random obstacle cells
# (--clutter-sizes, default 500 1000 2000); "render", ag-render of every
# stage of lab_a and of lab_a tiled 2 x 2 against that stage's compute, in
# CPU time (ag-bench-stage times the compute; ag-bench-exec each ag-render
# process on its own, start-up included). --tables picks which tables
# run (default all: maps runs scale clutter render).
#
# Usage: tools/bench-speed.sh [--runs N] [--floor-repeat R] [--build-dir DIR]
#                             [--no-build] [--data DIR] [--tables "LIST"]
#                             [--tiles "N..."] [--clutter-sizes "N..."]
set -euo pipefail
cd "$(dirname "$0")/.."

runs=3
floor_repeat=5
build_dir=build
build=1
data=../shared/data/areagraph/input
tables="maps runs scale clutter render"
tiles="1 2 4 6 8"
clutter_sizes="500 1000 2000"
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) runs="$2"; shift 2 ;;
    --floor-repeat) floor_repeat="$2"; shift 2 ;;
    --build-dir) build_dir="$2"; shift 2 ;;
    --no-build) build=0; shift ;;
    --data) data="$2"; shift 2 ;;
    --tables) tables="$2"; shift 2
      for table in $tables; do
        case "$table" in maps|runs|scale|clutter|render) ;; *)
          echo "bench-speed: unknown table '$table' (maps, runs, scale, clutter, render)" >&2; exit 2 ;;
        esac
      done ;;
    --tiles) tiles="$2"; shift 2 ;;
    --clutter-sizes) clutter_sizes="$2"; shift 2 ;;
    -h|--help) sed -n '2,32p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "bench-speed: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done

if [ "$build" = 1 ]; then
  if [ "$build_dir" != build ]; then
    echo "bench-speed: --build-dir needs --no-build (tools/build.sh builds into build/)" >&2
    exit 2
  fi
  tools/build.sh >&2
fi
bin="$build_dir/bin"
for tool in ag-import ag-inspect ag-bench-floor ag-bench-stage ag-run ag-render ag-bench-tile ag-bench-exec; do
  if [ ! -x "$bin/$tool" ]; then
    echo "bench-speed: $bin/$tool is missing; build it first" >&2
    exit 1
  fi
done
shopt -s nullglob
maps=("$data"/*.png)
if [ ${#maps[@]} -eq 0 ]; then
  echo "bench-speed: no maps in $data" >&2
  exit 1
fi

notes=()
stages=(clean voronoi prune cut merge)
if [ -x "$bin/ag-pipeline" ]; then
  mode=pipeline
else
  mode=stages
  notes+=("ag-pipeline is not built: the stage executables ran one by one.")
  for stage in "${stages[@]}"; do
    [ -x "$bin/ag-$stage" ] || notes+=("ag-$stage is not built: its column is empty.")
  done
fi
time_tool=()
if [ -x /usr/bin/time ]; then
  time_tool=(/usr/bin/time -f '%M' -a -o)
else
  notes+=("/usr/bin/time is missing (Debian package \`time\`): no memory figures.")
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

now_ms() { echo $(( $(date +%s%N) / 1000000 )); }

# Runs a command quietly, appending its peak RSS (KB) to $work/rss; a
# failure becomes a note (with the command's last output line), not an exit.
run_measured() {
  local status=0
  if [ ${#time_tool[@]} -gt 0 ]; then
    "${time_tool[@]}" "$work/rss" "$@" >>"$work/log" 2>&1 || status=$?
  else
    "$@" >>"$work/log" 2>&1 || status=$?
  fi
  if [ "$status" -ne 0 ]; then
    local last_line
    last_line=$(tail -1 "$work/log")
    notes+=("$(basename "$1") failed on $name (exit $status): $last_line")
  fi
}

# Median of the arguments (the upper middle one for an even count); "" for none.
median() {
  [ $# -gt 0 ] || { echo ""; return; }
  printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print v[int(NR / 2) + 1] }'
}

# The per-map table of the 16 maps (ag-import, then ag-pipeline).
maps_table() {
  load_before=$(cut -d' ' -f1-3 /proc/loadavg)
  echo "bench-speed: floor of ${#maps[@]} maps ($floor_repeat repeats)" >&2
  "$bin/ag-bench-floor" --repeat "$floor_repeat" "${maps[@]}" >"$work/floor.txt"

  rows=()
  declare -A total
  declare -A measured
  for column in floor import "${stages[@]}" stages wall; do
    total[$column]=0
    measured[$column]=0
  done
  peak_rss=0
  for map in "${maps[@]}"; do
    name=$(basename "${map%.*}")
    size=$(awk -v m="$name" '$1 == m { print $2 }' "$work/floor.txt")
    floor=$(awk -v m="$name" '$1 == m { print $NF }' "$work/floor.txt")
    declare -A samples=()
    rss_samples=()
    for ((run = 1; run <= runs; ++run)); do
      echo "bench-speed: $name run $run/$runs" >&2
      store="$work/store.db"
      rm -f "$store" "$store-wal" "$store-shm" "$work/rss"
      : >"$work/log"
      start=$(now_ms)
      run_measured "$bin/ag-import" --store "$store" --name "$name" "$map"
      imported=$(now_ms)
      if [ "$mode" = pipeline ]; then
        run_measured "$bin/ag-pipeline" --store "$store" --map "$name"
      else
        for stage in "${stages[@]}"; do
          if [ -x "$bin/ag-$stage" ]; then
            run_measured "$bin/ag-$stage" --store "$store" --map "$name"
          fi
        done
      fi
      finish=$(now_ms)
      samples[import]+=" $((imported - start))"
      samples[wall]+=" $((finish - start))"
      # The compute time the store recorded for each stage's head artifact.
      inspect=$("$bin/ag-inspect" --store "$store" --map "$name")
      sum=$((imported - start))
      for stage in "${stages[@]}"; do
        ms=$(awk -v s="$stage" '$1 == s && $NF == "*" { print $4 }' <<<"$inspect")
        if [ -n "$ms" ]; then
          samples[$stage]+=" $ms"
          sum=$(awk -v a="$sum" -v b="$ms" 'BEGIN { print a + b }')
        fi
      done
      samples[stages]+=" $sum"
      if [ -f "$work/rss" ]; then
        rss_samples+=("$(grep -E '^[0-9]+$' "$work/rss" | sort -n | tail -1)")
      fi
    done

    row="| $name | $size | $(printf '%.1f' "$floor")"
    total[floor]=$(awk -v a="${total[floor]}" -v b="$floor" 'BEGIN { print a + b }')
    for column in import "${stages[@]}" stages wall; do
      # shellcheck disable=SC2086
      value=$(median ${samples[$column]:-})
      if [ -z "$value" ]; then
        row+=" | –"
        continue
      fi
      row+=" | $(printf '%.0f' "$value")"
      measured[$column]=1
      total[$column]=$(awk -v a="${total[$column]}" -v b="$value" 'BEGIN { print a + b }')
    done
    # shellcheck disable=SC2086
    wall=$(median ${samples[wall]})
    row+=" | $(awk -v w="$wall" -v f="$floor" 'BEGIN { printf "%.1f", w / f }')"
    rss=$(median "${rss_samples[@]}")
    if [ -n "$rss" ]; then
      row+=" | $(awk -v k="$rss" 'BEGIN { printf "%.0f", k / 1024 }') |"
      if [ "$rss" -gt "$peak_rss" ]; then peak_rss=$rss; fi
    else
      row+=" | n/a |"
    fi
    rows+=("$row")
    unset samples
  done
  load_after=$(cut -d' ' -f1-3 /proc/loadavg)

  cpu=$(awk -F': ' '/model name/ { print $2; exit }' /proc/cpuinfo)
  echo "Speed of the Area Graph pipeline, $(date -u +%Y-%m-%d), $(nproc) cores ($cpu)."
  echo "Load average before/after: $load_before / $load_after. Medians of $runs runs per map,"
  echo "each from an empty store; floor: median of $floor_repeat. Times in ms."
  echo
  echo -n "| map | size | floor | import | clean | voronoi | prune | cut | merge | stages | total"
  echo " | total/floor | peak RSS MB |"
  echo "|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|"
  printf '%s\n' "${rows[@]}"
  totals="| **all ${#maps[@]} maps** | | $(printf '%.1f' "${total[floor]}")"
  for column in import "${stages[@]}" stages wall; do
    if [ "${measured[$column]}" = 1 ]; then
      totals+=" | $(printf '%.0f' "${total[$column]}")"
    else
      totals+=" | –"
    fi
  done
  totals+=" | $(awk -v w="${total[wall]}" -v f="${total[floor]}" 'BEGIN { printf "%.1f", w / f }')"
  if [ "$peak_rss" -gt 0 ]; then
    totals+=" | $(awk -v k="$peak_rss" 'BEGIN { printf "%.0f", k / 1024 }') (max) |"
  else
    totals+=" | n/a |"
  fi
  echo "$totals"
  echo
  echo "import: wall time of the ag-import process; clean..merge: compute time inside each stage"
  echo "(the store's elapsed_ms); stages: their sum; total: wall time of all processes of a run"
  echo "(start-up and store writes included); floor: ag-bench-floor (decode + Delaunay of the"
  echo "obstacle sites) in one process."
  echo
}

# shellcheck source=tools/bench-speed-series.sh
source tools/bench-speed-series.sh
series_load=$(cut -d' ' -f1-3 /proc/loadavg)
for table in $tables; do
  case "$table" in
    maps) maps_table ;;
    runs) runs_table ;;
    scale) scale_table ;;
    clutter) clutter_table ;;
    render) render_table ;;
    *) echo "bench-speed: unknown table '$table'" >&2; exit 2 ;;
  esac
done
echo "Run of $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores; load average at the start /"
echo "end: $series_load / $(cut -d' ' -f1-3 /proc/loadavg). Medians of $runs runs; floor: median of"
echo "$floor_repeat in one process (ag-bench-floor); CPU = user + system of all processes."
if [ ${#notes[@]} -gt 0 ]; then printf 'Note: %s\n' "${notes[@]}" | awk '!seen[$0]++'; fi
