#!/usr/bin/env bash
# The slowest run of every executable over every map: each map image in
# ../shared/data (not the ground truths or published results beside them) and
# rooms of 500, 1000 and 2000 px with 1 % of their cells random obstacles
# (ag-make-example-maps --clutter), the worst case of clutter. Per map, in a
# fresh store: ag-import, each stage executable, ag-pipeline --force, ag-run
# --force, ag-render of every stage, ag-export in every format (html too),
# ag-inspect (summary and --json) of every stage, ag-store verify, and ag-eval
# against the map's ground truth where the data has one. Prints a Markdown
# table on stdout: per executable the runs, the slowest map, its CPU time (user + system) and wall
# time, and how many runs took more than 2 s of CPU (the bar no tool may pass).
# CPU time is what counts on a machine shared with others; wall time is shown too.
# A benchmark: it checks nothing. Progress goes to stderr.
#
# --quick runs per map only ag-run --force (every stage computed), ag-render
# of every stage, ag-inspect --json of the Area Graph, ag-export --format html
# (the tool that reads every artifact) and ag-eval: the slowest of each kind,
# in a fifth of the time.
#
# Usage: tools/bench-tools.sh [--data DIR] [--build-dir DIR] [--no-build]
#                             [--limit N] [--no-clutter] [--quick] [--raw FILE]
# --raw FILE keeps every run's "tool<TAB>map<TAB>CPU s<TAB>wall s<TAB>exit" line.
set -euo pipefail
cd "$(dirname "$0")/.."

data=../shared/data
build_dir=build
build=1
limit=0
quick=0
raw=
clutter=(500 1000 2000)
while [ $# -gt 0 ]; do
  case "$1" in
    --data) data="$2"; shift 2 ;;
    --build-dir) build_dir="$2"; shift 2 ;;
    --no-build) build=0; shift ;;
    --limit) limit="$2"; shift 2 ;;
    --no-clutter) clutter=(); shift ;;
    --quick) quick=1; shift ;;
    --raw) raw="$2"; shift 2 ;;
    -h|--help) sed -n '2,22p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "bench-tools: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
if [ "$build" = 1 ]; then
  [ "$build_dir" = build ] || { echo "bench-tools: --build-dir needs --no-build" >&2; exit 2; }
  tools/build.sh >&2
fi
bin="$build_dir/bin"
[ -x /usr/bin/time ] || { echo "bench-tools: needs /usr/bin/time (package time)" >&2; exit 1; }
[ -x "$bin/ag-run" ] || { echo "bench-tools: no executables in $bin" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# "image<TAB>name<TAB>ground truth or -" for every map.
list_maps() {
  local f base
  shopt -s nullglob
  for f in "$data"/bormann/*.png "$data"/bormann/*.pgm; do
    case "$f" in *_gt_segmentation.png) continue ;; esac
    base="${f%.*}"
    if [ -f "${base}_gt_segmentation.png" ]; then
      printf '%s\tbormann/%s\t%s\n' "$f" "$(basename "$base")" "${base}_gt_segmentation.png"
    else
      printf '%s\tbormann/%s\t-\n' "$f" "$(basename "$base")"
    fi
  done
  for f in "$data"/areagraph/input/*.png "$data"/areagraph/input_afterRemoval/*.png; do
    printf '%s\t%s/%s\t%s\n' "$f" "$(basename "$(dirname "$f")")" "$(basename "${f%.*}")" \
      "$data/areagraph/GT/$(basename "$f")"
  done
  for f in "$data"/areagraph/mazes/*; do
    printf '%s\tmazes/%s\t-\n' "$f" "$(basename "${f%.*}")"
  done
  for f in "$data"/maoris/RobotMap/Maps/*.png; do
    printf '%s\trobotmap/%s\t%s\n' "$f" "$(basename "${f%.*}")" \
      "$data/maoris/RobotMap/GT/$(basename "$f")"
  done
  for size in "${clutter[@]}"; do
    "$bin/ag-make-example-maps" --clutter "$size" --out "$work" >/dev/null
    printf '%s\tclutter/%s\t-\n' "$work/clutter_$size.png" "$size"
  done
}

# timed TOOL MAP ARGS...: runs bin/TOOL, appends "TOOL<TAB>MAP<TAB>cpu<TAB>wall<TAB>exit".
timed() {
  local tool=$1 map=$2 status=0
  shift 2
  /usr/bin/time -f '%U %S %e' -o "$work/time" "$bin/$tool" "$@" >"$work/out" 2>"$work/err" ||
    status=$?
  awk -v tool="$tool" -v map="$map" -v status="$status" \
    'END { printf "%s\t%s\t%.2f\t%.2f\t%s\n", tool, map, $1 + $2, $3, status }' \
    "$work/time" >>"$work/times"
}

list_maps >"$work/maps"
[ "$limit" -gt 0 ] && head -n "$limit" "$work/maps" >"$work/m" && mv "$work/m" "$work/maps"
total=$(wc -l <"$work/maps")
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
done_maps=0
: >"$work/times"
while IFS=$'\t' read -r image name gt; do
  done_maps=$((done_maps + 1))
  echo "bench-tools: [$done_maps/$total] $name" >&2
  store="$work/s.db"
  rm -f "$store" "$store-wal" "$store-shm" "$work"/export.*
  map=(--store "$store" --map m)
  if [ "$quick" = 1 ]; then
    # ag-run names the map after the file.
    map=(--store "$store" --map "$(basename "${image%.*}")")
    timed ag-run "$name" --store "$store" --jobs 1 --force "$image"
    for stage in import clean voronoi prune cut merge; do
      timed ag-render "$name" "${map[@]}" --stage "$stage" --out "$work/render.png"
    done
    timed ag-inspect "$name" "${map[@]}" --stage merge --json
    timed ag-export "$name" "${map[@]}" --format html --out "$work/export.html"
    # For ag-eval; a map whose pipeline failed has none (a failed run above).
    "$bin/ag-export" "${map[@]}" --format labels --out "$work/export.labels" >/dev/null 2>&1 ||
      rm -f "$work/export.labels"
  else
    timed ag-import "$name" --store "$store" --name m "$image"
    for stage in clean voronoi prune cut merge; do timed "ag-$stage" "$name" "${map[@]}"; done
    timed ag-pipeline "$name" "${map[@]}" --force
    timed ag-run "$name" --store "$store" --jobs 1 --force "$image"
    for stage in import clean voronoi prune cut merge; do
      timed ag-render "$name" "${map[@]}" --stage "$stage" --out "$work/render.png"
      timed ag-inspect "$name" "${map[@]}" --stage "$stage"
      timed ag-inspect "$name" "${map[@]}" --stage "$stage" --json
    done
    for format in labels geojson osmag json html; do
      timed ag-export "$name" "${map[@]}" --format "$format" --out "$work/export.$format"
    done
    timed ag-store "$name" verify --store "$store"
  fi
  if [ "$gt" != - ] && [ -f "$gt" ]; then
    if [ -f "$work/export.labels" ]; then
      timed ag-eval "$name" --result "$work/export.labels" --gt "$gt"
    fi
  fi
done <"$work/maps"
load_after=$(cut -d' ' -f1-3 /proc/loadavg)
if [ -n "$raw" ]; then cp "$work/times" "$raw"; fi

echo "Slowest run of each executable over $total maps ($(date -u +%Y-%m-%d), load average" \
  "$load_before before, $load_after after; $(nproc) cores)."
echo
echo "| executable | runs | slowest map | CPU s | wall s | runs over 2 s CPU | failed runs |"
echo "|---|---|---|---|---|---|---|"
sort -t$'\t' -k1,1 -k3,3gr "$work/times" | awk -F'\t' '
  { runs[$1]++; if ($3 > 2) over[$1]++; if ($5 != 0) failed[$1]++ }
  !($1 in slowest) { slowest[$1] = $2; cpu[$1] = $3; wall[$1] = $4; order[++n] = $1 }
  END {
    for (i = 1; i <= n; i++) {
      t = order[i]
      printf "| %s | %d | %s | %.2f | %.2f | %d | %d |\n", t, runs[t], slowest[t], cpu[t], wall[t],
        over[t] + 0, failed[t] + 0
    }
  }'
