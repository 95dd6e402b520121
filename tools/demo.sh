#!/usr/bin/env bash
# The main job end to end on a shipped example map: installs what is missing,
# builds, turns the map into an Area Graph in out/demo.db, and writes
# out/MAP.html (every stage in the browser: open it first), a picture of
# every stage and the exports to out/.
#   tools/demo.sh [MAP] [--set stage.field=value]...
set -euo pipefail
cd "$(dirname "$0")/.."
MAP=examples/office_small.png
if [ $# -gt 0 ] && [[ "$1" != --* ]]; then MAP=$1; shift; fi
mkdir -p out
echo "demo: installing what is missing and building what it runs (a fresh machine takes about 8 minutes; log in out/build.log)"
tools/build.sh ag-run ag-render ag-export ag-inspect >out/build.log 2>&1 ||
  { tail -n 30 out/build.log >&2; echo "demo: build failed (out/build.log)" >&2; exit 1; }
echo "demo: running the pipeline on $MAP"
STORE=out/demo.db
BIN=build/bin
name=$(basename "${MAP%.*}")
"$BIN/ag-run" --store "$STORE" --jobs 1 "$@" "$MAP"
for stage in clean voronoi prune cut merge; do
  "$BIN/ag-render" --store "$STORE" --map "$name" --stage "$stage" --out "out/$name-$stage.png"
done
"$BIN/ag-export" --store "$STORE" --map "$name" --format html --out "out/$name.html"
"$BIN/ag-export" --store "$STORE" --map "$name" --format geojson --out "out/$name.geojson"
"$BIN/ag-export" --store "$STORE" --map "$name" --format osmag --out "out/$name.osm"
"$BIN/ag-export" --store "$STORE" --map "$name" --format labels --out "out/$name-labels.png"
"$BIN/ag-export" --store "$STORE" --map "$name" --format preview --out "out/$name-preview.png"
"$BIN/ag-export" --store "$STORE" --map "$name" --format json --out "out/$name.json"
"$BIN/ag-inspect" --store "$STORE" --map "$name"
echo "pictures: out/$name-{clean,voronoi,prune,cut,merge,preview}.png; exports: out/$name.geojson, out/$name.osm, out/$name.json (README: Outputs)"
echo "open first: out/$name.html in a browser (every stage as a layer; hover, zoom, options, W)"
