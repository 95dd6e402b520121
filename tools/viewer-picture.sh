#!/usr/bin/env bash
# Makes docs/images/viewer.png, the README's picture of the HTML viewer: the
# page of examples/office_small.png (default options) in headless chromium,
# with the Topology Graph, the areas, passages and doors, and one area
# selected.   tools/viewer-picture.sh [--build DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
BIN=build/bin
if [ "${1:-}" = --build ]; then BIN=$2/bin; else tools/build.sh >/dev/null; fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$BIN/ag-run" --store "$work/store.db" --jobs 1 examples/office_small.png >/dev/null 2>&1
"$BIN/ag-export" --store "$work/store.db" --map office_small --format html --out "$work/page.html"
OFFLINE=()
if unshare -n true 2>/dev/null; then OFFLINE=(unshare -n); fi
"${OFFLINE[@]}" chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
  --disable-background-networking --disable-component-update --disable-sync --hide-scrollbars \
  --user-data-dir="$work/profile" --window-size=980,560 --screenshot=docs/images/viewer.png \
  "file://$work/page.html#layers=grid,topology,areas,passages,widths&select=area/2" 2>/dev/null
echo "wrote docs/images/viewer.png ($(stat -c %s docs/images/viewer.png) bytes)"
