#!/usr/bin/env bash
# The main job end to end on a shipped example map: installs, builds, imports
# examples/office_small.png into out/demo.db and shows what the store holds.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/build.sh
mkdir -p out
MAP=${1:-examples/office_small.png}
STORE=out/demo.db
build/bin/ag-import --store "$STORE" "$MAP"
name=$(basename "${MAP%.*}")
build/bin/ag-inspect --store "$STORE"
build/bin/ag-inspect --store "$STORE" --map "$name"
build/bin/ag-inspect --store "$STORE" --map "$name" --stage import
