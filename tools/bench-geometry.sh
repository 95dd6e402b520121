#!/usr/bin/env bash
# Geometry benchmark of the Area Graph as a map. Runs the pipeline with the
# defaults (plus any --set) on the Area Graph paper's 16 maps and MAORIS' 20
# RobotMap maps and prints, per map and in total: areas, vertices per area
# (outer ring: median, max; max with holes), holes (and those under
# merge.min_hole_m2), passages (and
# those whose end points are vertices of both areas' outlines), pairs of
# areas that overlap, the largest distance from a simplified outline to the
# raster's outline, and the MCC (MAORIS' code) of the raster partition and of
# the polygons as ag-export draws them. Statistics by ag-bench-geometry,
# MCC by ag-eval. --build DIR uses the executables of an existing build.
#
#   tools/bench-geometry.sh [--data DIR] [--out DIR] [--build DIR] [--set k=v]...
set -euo pipefail
cd "$(dirname "$0")/.."
DATA=../shared/data
OUT=out/bench-geometry
BUILD=
SETS=()
while [ $# -gt 0 ]; do
  case "$1" in
    --data) DATA=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    --build) BUILD=$2; shift 2 ;;
    --set) SETS+=(--set "$2"); shift 2 ;;
    -h|--help) sed -n '2,13p' "$0"; exit 0 ;;
    *) echo "bench-geometry: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
[ -d "$DATA/areagraph/input" ] || { echo "bench-geometry: no data at $DATA (use --data)" >&2; exit 1; }
if [ -n "$BUILD" ]; then
  BIN=$BUILD/bin
else
  tools/build.sh >/dev/null
  BIN=build/bin
fi
[ -x "$BIN/ag-bench-geometry" ] || { echo "bench-geometry: no ag-bench-geometry in $BIN" >&2; exit 1; }
rm -rf "$OUT"
mkdir -p "$OUT"

# mcc_column DIR GT [ag-eval flags] -> "map<TAB>mcc" lines, plus "mean<TAB>x"
mcc_column() {
  local dir=$1 gt=$2
  shift 2
  { "$BIN/ag-eval" --dataset --results "$dir" --gt "$gt" --mcc-variant maoris "$@" 2>/dev/null ||
    true; } | awk -F'|' 'NR > 2 { gsub(/[ *]/, "", $2); gsub(/[ *]/, "", $3); print $2 "\t" $3 }'
}

run_dataset() {  # run_dataset NAME IMAGE_DIR GT_DIR [ag-eval flags]
  local name=$1 images=$2 gt=$3
  shift 3
  local store=$OUT/$name.db maps=()
  mkdir -p "$OUT/$name/raster" "$OUT/$name/polygons"
  for image in "$images"/*.png; do
    local map
    map=$(basename "$image" .png)
    echo "$name/$map" >&2
    "$BIN/ag-import" --store "$store" --name "$map" "$image" >/dev/null
    if "$BIN/ag-pipeline" --store "$store" --map "$map" "${SETS[@]}" >"$OUT/$name/$map.log" 2>&1; then
      maps+=("$map")
    else
      echo "bench-geometry: $map failed: $(tail -n 1 "$OUT/$name/$map.log")" >&2
    fi
  done
  "$BIN/ag-bench-geometry" --store "$store" --labels "$OUT/$name" \
    --vertex-list "$OUT/$name.vertices" "${maps[@]}" >"$OUT/$name.tsv"
  mcc_column "$OUT/$name/raster" "$gt" "$@" >"$OUT/$name.mcc-raster"
  mcc_column "$OUT/$name/polygons" "$gt" "$@" >"$OUT/$name.mcc-polygons"
}

# table TITLE NAME... -> Markdown table of the maps of the named datasets and
# their total (vertex medians over all areas, MCC means over all maps).
table() {
  local title=$1
  shift
  local tsvs=() vertices=() raster=() polygons=()
  for name in "$@"; do
    tsvs+=("$OUT/$name.tsv"); vertices+=("$OUT/$name.vertices")
    raster+=("$OUT/$name.mcc-raster"); polygons+=("$OUT/$name.mcc-polygons")
  done
  echo
  echo "### $title"
  echo
  echo "| map | areas | vertices/area median | max | max with holes | holes | holes < min | passages | on both outlines | overlapping pairs | max distance m | MCC raster | MCC polygons |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|"
  local median
  median=$(cut -f2 "${vertices[@]}" | sort -n | awk '{ v[NR] = $1 } END {
    if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }')
  cat "${raster[@]}" | grep -v '^mean' | sed 's/^/R\t/' >"$OUT/.mcc"
  cat "${polygons[@]}" | grep -v '^mean' | sed 's/^/P\t/' >>"$OUT/.mcc"
  awk -F'\t' -v median="$median" '
    FILENAME ~ /\.mcc$/ { mcc[$1, $2] = $3; next }
    {
      m = $1
      r = ((("R", m) in mcc) ? mcc["R", m] : "-"); p = ((("P", m) in mcc) ? mcc["P", m] : "-")
      print "| " m " | " $2 " | " $3 " | " $4 " | " $12 " | " $5 " | " $6 " | " $7 " | " $8 " | " $9 " | " $11 " | " r " | " p " |"
      areas += $2; if ($4 > vmax) vmax = $4; if ($12 > hmax) hmax = $12; holes += $5; small += $6; passages += $7
      both += $8; overlaps += $9; if ($11 != "-" && $11 > dmax) dmax = $11
      if (r != "-") { rs += r; rn++ } if (p != "-") { ps += p; pn++ }
    }
    END {
      printf "| **total** | %d | %s | %d | %d | %d | %d | %d | %d (%.1f %%) | %d | %.3f | %.3f | %.3f |\n",
        areas, median, vmax, hmax, holes, small, passages, both, passages ? 100 * both / passages : 100,
        overlaps, dmax, rn ? rs / rn : 0, pn ? ps / pn : 0
    }' "$OUT/.mcc" "${tsvs[@]}"
}

run_dataset areagraph "$DATA/areagraph/input" "$DATA/areagraph/GT"
run_dataset robotmap "$DATA/maoris/RobotMap/Maps" "$DATA/maoris/RobotMap/GT" --gt-style maoris-lines

echo "## Area Graph geometry, $(date -u +%Y-%m-%d)${SETS[*]:+ (${SETS[*]})}"
table "areagraph/ (16 maps)" areagraph
table "maoris/RobotMap (20 maps)" robotmap
table "all 36 maps (total only)" areagraph robotmap | grep -E '^(#|$|\| map|\|---|\| \*\*total)'
