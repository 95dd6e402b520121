#!/usr/bin/env bash
# Segmentation quality benchmark. Runs the pipeline on the Area Graph paper's
# 16 maps (with the defaults, which estimate W; with the paper's per-map W and
# noise from data_setting; and with the fixed W = 1.25 m) and on MAORIS' 20
# RobotMap maps (defaults), scores every result with ag-eval against the human
# ground truth, and prints Markdown tables that also score the published
# results shipped with the data. --build DIR uses the executables of an
# existing build (DIR/bin) instead of building build/.
#
#   tools/bench-quality.sh [--data DIR] [--out DIR] [--build DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
DATA=../shared/data
OUT=out/bench-quality
BUILD=
while [ $# -gt 0 ]; do
  case "$1" in
    --data) DATA=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    --build) BUILD=$2; shift 2 ;;
    -h|--help) sed -n '2,10p' "$0"; exit 0 ;;
    *) echo "bench-quality: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
AG=$DATA/areagraph
RM=$DATA/maoris/RobotMap
[ -d "$AG/input" ] || { echo "bench-quality: no data at $AG/input (use --data)" >&2; exit 1; }
if [ -n "$BUILD" ]; then
  BIN=$BUILD/bin
  [ -x "$BIN/ag-pipeline" ] || { echo "bench-quality: no ag-pipeline in $BIN" >&2; exit 1; }
else
  tools/build.sh >/dev/null
  BIN=build/bin
fi
rm -rf "$OUT"
mkdir -p "$OUT"/{auto,strategy,fixed,maoris}
STORE=$OUT/store.db

# data_setting lists, per section, "<map>.png <value>" lines.
setting() {  # setting SECTION_PREFIX MAP -> value or empty
  awk -v section="$1" -v map="$2.png" '
    /^[a-zA-Z].*:$/ || /^[a-z].*\):?$/ { in_section = index($0, section) == 1 }
    in_section && $1 == map { print $2; exit }' "$AG/data_setting"
}

run_map() {  # run_map IMAGE NAME OUTDIR [--set k=v]...
  local image=$1 name=$2 outdir=$3
  shift 3
  "$BIN/ag-import" --store "$STORE" --name "$name" "$image" >/dev/null
  if "$BIN/ag-pipeline" --store "$STORE" --map "$name" "$@" >"$outdir/$name.log" 2>&1; then
    "$BIN/ag-export" --store "$STORE" --map "$name" --format labels --out "$outdir/$name.png" >/dev/null
  else
    echo "bench-quality: $name failed: $(tail -n 1 "$outdir/$name.log")" >&2
  fi
}

for image in "$AG"/input/*.png; do
  name=$(basename "$image" .png)
  w=$(setting "w (m) according" "$name")
  noise=$(setting "noise percentage" "$name")
  noise_set=()
  [ -n "$noise" ] && noise_set=(--set "clean.outlier_percent=$noise")
  echo "areagraph/$name: W=${w:-1.25 (none given)} noise=${noise:-default}" >&2
  run_map "$image" "$name" "$OUT/auto"
  run_map "$image" "$name" "$OUT/strategy" --set "cut.room_width_m=${w:-1.25}" "${noise_set[@]}"
  run_map "$image" "$name" "$OUT/fixed" --set cut.room_width_m=1.25 "${noise_set[@]}"
done
for image in "$RM"/Maps/*.png; do
  name=$(basename "$image" .png)
  echo "maoris/$name" >&2
  run_map "$image" "$name" "$OUT/maoris"
done

# mcc_column DIR GT [ag-eval flags] -> "map<TAB>mcc" lines, plus "mean<TAB>x"
mcc_column() {
  local dir=$1 gt=$2
  shift 2
  { "$BIN/ag-eval" --dataset --results "$dir" --gt "$gt" "$@" 2>/dev/null || true; } |
    awk -F'|' 'NR > 2 { gsub(/[ *]/, "", $2); gsub(/[ *]/, "", $3); print $2 "\t" $3 }'
}

# join_table TITLE LABEL:FILE... -> Markdown table with one MCC column per file
join_table() {
  local title=$1
  shift
  echo
  echo "### $title"
  echo
  awk -F'\t' -v n=$# '
    FNR == 1 { file++ }
    { if (!($1 in seen)) { seen[$1] = 1; order[++rows] = $1 } value[$1, file] = $2 }
    END {
      for (r = 1; r <= rows; r++) {
        line = "| " order[r]
        for (f = 1; f <= n; f++) line = line " | " ((order[r], f) in value ? value[order[r], f] : "-")
        print line " |"
      }
    }' "${@#*:}" | {
    header="| map"; rule="|---"
    for column in "$@"; do header="$header | ${column%%:*}"; rule="$rule|---"; done
    echo "$header |"; echo "$rule|"; cat
  }
}

T=$OUT/tables
mkdir -p "$T"
for variant in standard maoris; do
  flags=(--mcc-variant "$variant")
  mcc_column "$OUT/auto" "$AG/GT" "${flags[@]}" >"$T/ours-auto-$variant"
  mcc_column "$OUT/strategy" "$AG/GT" "${flags[@]}" >"$T/ours-strategy-$variant"
  mcc_column "$OUT/fixed" "$AG/GT" "${flags[@]}" >"$T/ours-fixed-$variant"
  mcc_column "$AG/strategy_w" "$AG/GT" "${flags[@]}" --drop-result-px 100 >"$T/paper-strategy-$variant"
  mcc_column "$AG/w=1_25" "$AG/GT" "${flags[@]}" --drop-result-px 100 >"$T/paper-fixed-$variant"
  rm_flags=("${flags[@]}" --gt-style maoris-lines)
  mcc_column "$OUT/maoris" "$RM/GT" "${rm_flags[@]}" >"$T/ours-maoris-$variant"
  mcc_column "$RM/maoris/t03m01R40D50" "$RM/GT" "${rm_flags[@]}" >"$T/maoris-$variant"
  mcc_column "$RM/Voronoi" "$RM/GT" "${rm_flags[@]}" >"$T/voronoi-$variant"
  mcc_column "$RM/DuDe_results/Incremental" "$RM/GT" "${rm_flags[@]}" >"$T/dude-$variant"
done

echo "## Segmentation quality, $(date -u +%Y-%m-%d)"
for variant in standard maoris; do
  join_table "areagraph/ (16 maps), MCC ($variant)" \
    "ours, defaults (auto W):$T/ours-auto-$variant" "ours, strategy W:$T/ours-strategy-$variant" "ours, W = 1.25:$T/ours-fixed-$variant" \
    "paper code, strategy W:$T/paper-strategy-$variant" "paper code, W = 1.25:$T/paper-fixed-$variant"
  join_table "maoris/RobotMap (20 maps), MCC ($variant)" \
    "ours, defaults:$T/ours-maoris-$variant" "MAORIS:$T/maoris-$variant" \
    "Bormann Voronoi:$T/voronoi-$variant" "DuDe:$T/dude-$variant"
done
