#!/usr/bin/env bash
# The main job end to end on a shipped example map: installs what is missing,
# builds, turns the map into an Area Graph in out/demo.db, and writes a
# picture of every stage plus the exports to out/.
#   tools/demo.sh [MAP] [--set stage.field=value]...
set -euo pipefail
cd "$(dirname "$0")/.."
MAP=examples/office_small.png
if [ $# -gt 0 ] && [[ "$1" != --* ]]; then MAP=$1; shift; fi
tools/build.sh >/dev/null
mkdir -p out
STORE=out/demo.db
BIN=build/bin
name=$(basename "${MAP%.*}")
"$BIN/ag-import" --store "$STORE" "$MAP"
"$BIN/ag-pipeline" --store "$STORE" --map "$name" "$@"
for stage in clean voronoi prune cut merge; do
  "$BIN/ag-render" --store "$STORE" --map "$name" --stage "$stage" --out "out/$name-$stage.png"
done
"$BIN/ag-export" --store "$STORE" --map "$name" --format geojson --out "out/$name.geojson"
"$BIN/ag-export" --store "$STORE" --map "$name" --format osmag --out "out/$name.osm"
"$BIN/ag-export" --store "$STORE" --map "$name" --format labels --out "out/$name-labels.png"
"$BIN/ag-inspect" --store "$STORE" --map "$name"
echo "pictures: out/$name-{clean,voronoi,prune,cut,merge}.png; exports: out/$name.geojson, out/$name.osm"
