#!/usr/bin/env bash
# Viewer page benchmark: runs ag-run --report on Bormann's maps in
# ../shared/data (every map but the ground truth), then measures the largest
# viewer pages in headless chromium (offline, fresh profile): the file size,
# the page's own time to the end of its script (data-ready: parsing the HTML
# and the JSON, building the default layers), and the wall time of a
# screenshot (load, layout, paint, capture) with the default layers and with
# every layer on, each minus that of a blank page taken just before it.
# Medians of --runs runs; prints a Markdown table. Targets: under 5 MB, open in under 2 s.
#
#   tools/bench-viewer.sh [--data DIR] [--out DIR] [--build DIR] [--top N] [--runs N] [--reuse]
# --reuse measures the pages of an earlier run in --out again.
set -euo pipefail
cd "$(dirname "$0")/.."
DATA=../shared/data
OUT=out/bench-viewer
BUILD=
TOP=6
RUNS=3
REUSE=
while [ $# -gt 0 ]; do
  case "$1" in
    --data) DATA=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    --build) BUILD=$2; shift 2 ;;
    --top) TOP=$2; shift 2 ;;
    --runs) RUNS=$2; shift 2 ;;
    --reuse) REUSE=1; shift ;;
    -h|--help) sed -n '2,14p' "$0"; exit 0 ;;
    *) echo "bench-viewer: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
[ -d "$DATA/bormann" ] || { echo "bench-viewer: no data at $DATA/bormann (use --data)" >&2; exit 1; }
command -v chromium >/dev/null || { echo "bench-viewer: chromium is missing (tools/install-deps.sh)" >&2; exit 1; }
if [ -n "$BUILD" ]; then
  BIN=$BUILD/bin
else
  tools/build.sh >/dev/null
  BIN=build/bin
fi
if [ -z "$REUSE" ] || [ ! -d "$OUT/report/maps" ]; then
  rm -rf "$OUT"
  mkdir -p "$OUT/maps"
  for image in "$DATA"/bormann/*.png; do
    case "$image" in *_gt_segmentation.png) continue ;; esac
    ln -s "$(realpath "$image")" "$OUT/maps/"
  done
  "$BIN/ag-run" --store "$OUT/store.db" --report "$OUT/report" "$OUT/maps" >"$OUT/run.log" 2>&1 ||
    echo "bench-viewer: some maps failed (see $OUT/run.log)" >&2
fi

OFFLINE=()
if unshare -n true 2>/dev/null; then OFFLINE=(unshare -n); fi
chrome() {  # chrome ARGS... : headless chromium, fresh profile, no network
  local profile
  profile=$(mktemp -d)
  "${OFFLINE[@]}" timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-quic \
    --no-first-run --disable-background-networking --disable-component-update --disable-sync \
    --hide-scrollbars --window-size=1400,900 --user-data-dir="$profile" "$@" 2>/dev/null
  rm -rf "$profile"
}
now_ms() { echo $(($(date +%s%N) / 1000000)); }
median() { sort -n | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
shot_ms() {  # shot_ms URL -> wall ms of one screenshot
  local start
  start=$(now_ms)
  chrome --screenshot="$OUT/shot.png" "$1" >/dev/null
  echo $(($(now_ms) - start))
}
opening_ms() {  # opening_ms URL -> median over RUNS of (screenshot of URL - screenshot of a blank page)
  for _ in $(seq "$RUNS"); do
    local blank page
    blank=$(shot_ms "data:text/html,<p>blank</p>")
    page=$(shot_ms "$1")
    echo $((page - blank))
  done | median
}
ready_ms() {  # ready_ms URL -> median of the page's data-ready
  for _ in $(seq "$RUNS"); do
    chrome --dump-dom "$1" | grep -o 'data-ready="[0-9]*"' | grep -o '[0-9]*'
  done | median
}

blanks=$(for _ in $(seq "$RUNS"); do shot_ms "data:text/html,<p>blank</p>"; done | median)
ALL="#layers=grid,clean,hugging,voronoi,topology,rooms,areas,passages,widths"
pages=$(ls -S "$OUT"/report/maps/*.html | sed -n "1,${TOP}p")  # sed reads all: no SIGPIPE
echo "### Viewer pages of the $TOP largest of $(ls "$OUT"/report/maps | wc -l) Bormann maps ($(date -u +%Y-%m-%d), median of $RUNS)"
echo
echo "| map | size px | page MB | script done ms | open, default layers ms | open, all layers ms |"
echo "|---|---:|---:|---:|---:|---:|"
for page in $pages; do
  url="file://$(realpath "$page")"
  width=$(grep -o '"width_px":[0-9]*' "$page" | head -n 1 | grep -o '[0-9]*$')
  height=$(grep -o '"height_px":[0-9]*' "$page" | head -n 1 | grep -o '[0-9]*$')
  mb=$(awk -v b="$(stat -c %s "$page")" 'BEGIN { printf "%.2f", b / 1048576 }')
  ready=$(ready_ms "$url")
  default=$(opening_ms "$url")
  all=$(opening_ms "$url$ALL")
  echo "| $(basename "$page" .html) | ${width}x${height} | $mb | $ready | $default | $all |"
done
echo
echo "A screenshot of a blank page took ${blanks} ms (median); each opening time above is a page's" \
  "screenshot minus the blank one just before it, median of $RUNS pairs. Load average at the end:" \
  "$(cut -d' ' -f1-3 /proc/loadavg). Largest page of all:" \
  "$(ls -S "$OUT"/report/maps/*.html | sed -n 1p | xargs stat -c '%s %n' | awk '{ printf "%.2f MB (%s)", $1 / 1048576, $2 }')."
