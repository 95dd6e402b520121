#!/usr/bin/env bash
# Regenerates the pictures of docs/quality.md: for a few benchmark maps the
# input (ag-render of the import), our result with the defaults (ag-render of
# the Area Graph) and the ground truth as ag-eval reads it (ag-eval
# --gt-picture), a generated public building likewise, plus the maze and
# the RoboCup Rescue map of the Area Graph paper (input and result; they have
# no ground truth). All drawn by the project's tools from its own output; no
# dataset image is copied.
#
#   tools/render-quality-pictures.sh [--data DIR] [--out DIR] [--build DIR] [--width PX]
set -euo pipefail
cd "$(dirname "$0")/.."
DATA=../shared/data
OUT=docs/images
BUILD=
WIDTH=320
while [ $# -gt 0 ]; do
  case "$1" in
    --data) DATA=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    --build) BUILD=$2; shift 2 ;;
    --width) WIDTH=$2; shift 2 ;;
    -h|--help) sed -n '2,10p' "$0"; exit 0 ;;
    *) echo "render-quality-pictures: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
AG=$DATA/areagraph
RM=$DATA/maoris/RobotMap
[ -d "$AG/input" ] || { echo "render-quality-pictures: no data at $AG (use --data)" >&2; exit 1; }
if [ -n "$BUILD" ]; then BIN=$BUILD/bin; else tools/build.sh >/dev/null; BIN=build/bin; fi
mkdir -p "$OUT"
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
STORE=$WORK/store.db

draw() {  # draw IMAGE NAME [GT [ag-eval flags]...]
  local image=$1 name=$2
  shift 2
  "$BIN/ag-import" --store "$STORE" --name "$name" "$image" >/dev/null
  "$BIN/ag-pipeline" --store "$STORE" --map "$name" >/dev/null
  "$BIN/ag-render" --store "$STORE" --map "$name" --stage import --scale 1 --width "$WIDTH" \
    --out "$OUT/${name}_input.png" >/dev/null
  "$BIN/ag-render" --store "$STORE" --map "$name" --stage merge --scale 1 --width "$WIDTH" \
    --out "$OUT/${name}_ours.png" >/dev/null
  if [ $# -gt 0 ]; then
    "$BIN/ag-eval" --gt "$@" --gt-picture "$OUT/${name}_gt.png" --picture-width "$WIDTH" >/dev/null
  fi
}

for name in freiburg_building52 sistD; do
  draw "$AG/input/$name.png" "$name" "$AG/GT/$name.png"
done
for name in office_d lab_intel; do
  draw "$RM/Maps/$name.png" "$name" "$RM/GT/$name.png" --gt-style maoris-lines
done
# A generated public building (the project's own generator: its image may
# be shipped), the first floor of the held-out part.
"$BIN/ag-make-benchmark" --part public-held-out --count 1 "$WORK/public" >/dev/null
for image in "$WORK"/public/maps/*.png; do
  name=$(basename "$image" .png)
  # Twice as wide: the building is 100-200 m across.
  WIDTH=$((2 * WIDTH)) draw "$image" "$name" "$WORK/public/gt/$name.png" --gt-style labels
done
draw "$AG/mazes/maze.jpg" maze
draw "$AG/mazes/singa.png" robocup_rescue
du -ch "$OUT"/*.png | tail -n 1
