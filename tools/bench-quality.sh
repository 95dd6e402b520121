#!/usr/bin/env bash
# Segmentation quality benchmark over five sets of maps, every result scored
# by ag-eval against human (or drawn) ground truth, MAORIS' per-zone MCC:
# - areagraph/: the Area Graph paper's 16 maps, with the defaults, with the
#   paper's per-map W and noise (data_setting) and with W = 1.25 m; the paper
#   code's shipped results are scored alongside;
# - RobotMap: MAORIS' 20 maps, with MAORIS', Bormann's Voronoi and DuDe's
#   shipped results alongside;
# - bormann/: Bormann's 20 maps in all four variants (plain, furnitures,
#   trashbins, furnitures + trashbins: 79 maps), scored against the plain
#   map's line ground truth (lab_b_scan_furnitures_trashbins was published at
#   2/3 scale: it runs at 0.075 m/px and its result is scaled up to the GT);
# - tuning and held-out: the two parts of ag-make-benchmark's office floors
#   (generated floors with drawn ground truth), and public-tuning and
#   public-held-out, its large public buildings. Constants are chosen on the
#   tuning parts; the held-out parts are only reported. Their ground truth has
#   kinds, so these sets also report kind accuracy (ag-eval, with ag-export
#   --format kinds).
# Every set also runs with W = 1.25 m (the defaults otherwise: a number for W
# skips the width estimate, so the cut pass CLOSE_WALL_DOORS, which closes the doors the
# estimate finds, closes none there; that column differs from the defaults in
# W and in that rule, docs/quality.md, "How to score") and with the
# paper's behaviour (examples/options/paper.pbtxt); the generated floors also
# with W from their true door and corridor widths (the paper's rule).
# Prints a summary and per-map tables (Markdown) on stdout.
#
#   tools/bench-quality.sh [--data DIR] [--out DIR] [--build DIR] [--sets LIST]
#                          [--options FILE] [--set KEY=VALUE]... [--jobs N]
#                          [--fixed-widths LIST]
#
# --sets: comma-separated subset of areagraph,robotmap,bormann,tuning,held-out,
# public-tuning,public-held-out (default: all seven). --options and --set
# change the "ours, defaults" runs only (to try an option against the same
# tables). --fixed-widths: comma-separated fixed W (m) to run every set with
# (default 1.25, the summary's fixed column; with more, a table of each).
set -euo pipefail
cd "$(dirname "$0")/.."
DATA=../shared/data
OUT=out/bench-quality
BUILD=
SETS=areagraph,robotmap,bormann,tuning,held-out,public-tuning,public-held-out
GENERATED="tuning held-out public-tuning public-held-out"
JOBS=2
WIDTHS=1.25
OURS=()
while [ $# -gt 0 ]; do
  case "$1" in
    --data) DATA=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    --build) BUILD=$2; shift 2 ;;
    --sets) SETS=$2; shift 2 ;;
    --options) OURS+=(--options "$2"); shift 2 ;;
    --set) OURS+=(--set "$2"); shift 2 ;;
    --jobs) JOBS=$2; shift 2 ;;
    --fixed-widths) WIDTHS=$2; shift 2 ;;
    -h|--help) sed -n '2,36p' "$0"; exit 0 ;;
    *) echo "bench-quality: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
for set in ${SETS//,/ }; do
  case "$set" in areagraph|robotmap|bormann|tuning|held-out|public-tuning|public-held-out) ;;
    *) echo "bench-quality: unknown set '$set' (areagraph, robotmap, bormann, tuning, held-out," \
         "public-tuning, public-held-out)" >&2
       exit 2 ;;
  esac
done
for w in ${WIDTHS//,/ }; do
  [[ "$w" =~ ^[0-9]+(\.[0-9]+)?$ ]] || { echo "bench-quality: bad fixed width '$w'" >&2; exit 2; }
done
FIRST_W=${WIDTHS%%,*}
wanted() { [[ ",$SETS," == *",$1,"* ]]; }
AG=$DATA/areagraph
RM=$DATA/maoris/RobotMap
BM=$DATA/bormann
if wanted areagraph || wanted robotmap || wanted bormann; then
  [ -d "$AG/input" ] || { echo "bench-quality: no data at $AG/input (use --data)" >&2; exit 1; }
fi
if [ -n "$BUILD" ]; then
  BIN=$BUILD/bin
  [ -x "$BIN/ag-run" ] || { echo "bench-quality: no ag-run in $BIN" >&2; exit 1; }
else
  tools/build.sh >/dev/null
  BIN=build/bin
fi
PAPER=(--options examples/options/paper.pbtxt)
FIXED=(--set "cut.room_width_m=$FIRST_W")
rm -rf "$OUT"
mkdir -p "$OUT/manifests"

# run MANIFEST OUTDIR [ag-run flags]: runs every map of the manifest and
# exports its labels to OUTDIR/<name>.png (a failed map gets no file), and
# with KINDS=1 the areas' kinds to OUTDIR/<name>.kinds.tsv. Each run has its
# own store, removed afterwards: a store of every run would grow to gigabytes.
KINDS=0
run() {
  local manifest=$1 outdir=$2
  shift 2
  mkdir -p "$outdir"
  echo "bench-quality: $outdir" >&2
  local store=$outdir.db
  "$BIN/ag-run" --store "$store" --jobs "$JOBS" "$@" "$manifest" >"$outdir.log" 2>&1 ||
    grep -i "failed" "$outdir.log" | grep -v " 0 failed" >&2 || true
  # A map without an Area Graph gets no file (ag-export names it).
  "$BIN/ag-export" --store "$store" --all --format labels --out "$outdir" >/dev/null ||
    echo "bench-quality: $outdir: a map has no result" >&2
  if [ "$KINDS" = 1 ]; then
    "$BIN/ag-export" --store "$store" --all --format kinds --out "$outdir" >/dev/null 2>&1 || true
  fi
  rm -f "$store" "$store-wal" "$store-shm"
}

# mcc DIR GT [ag-eval flags] -> "map<TAB>mcc" lines, then "mean<TAB>x" and
# "median<TAB>x"; where results and GT have kinds, also DIR.kinds: the same
# lines with the kind accuracy.
mcc() {
  local dir=$1 gt=$2
  shift 2
  local table
  table=$("$BIN/ag-eval" --dataset --results "$dir" --gt "$gt" "$@" 2>/dev/null || true)
  awk -F'|' 'NR > 2 { gsub(/[ *]/, "", $2); gsub(/[ *]/, "", $3); print $2 "\t" $3 }' <<<"$table"
  if head -1 <<<"$table" | grep -q "kind accuracy"; then
    awk -F'|' 'NR > 2 { gsub(/[ *]/, "", $2); gsub(/[ *]/, "", $7); print $2 "\t" $7 }' \
      <<<"$table" >"$dir.kinds"
  fi
}

# table TITLE LABEL:FILE... -> Markdown table with one MCC column per file
table() {
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

mean_of() { awk -F'\t' '$1 == "mean" { print $2 }' "$1" 2>/dev/null || true; }
count_of() { grep -cvE '^(mean|median)	' "$1" 2>/dev/null || true; }

T=$OUT/tables
mkdir -p "$T"
SUMMARY=$T/summary
: >"$SUMMARY"
# summary_row NAME FILE_DEFAULTS FILE_FIXED FILE_PAPER PUBLISHED_TEXT
summary_row() {
  printf '| %s | %s | **%s** | %s | %s | %s |\n' "$1" "$(count_of "$2")" "$(mean_of "$2")" \
    "$(mean_of "$3")" "$(mean_of "$4")" "$5" >>"$SUMMARY"
}

# data_setting lists, per section, "<map>.png <value>" lines.
setting() {  # setting SECTION_PREFIX MAP -> value or empty
  awk -v section="$1" -v map="$2.png" '
    /^[a-zA-Z].*:$/ || /^[a-z].*\):?$/ { in_section = index($0, section) == 1 }
    in_section && $1 == map { print $2; exit }' "$AG/data_setting"
}

if wanted areagraph; then
  M=$OUT/manifests/areagraph.tsv
  S=$OUT/manifests/areagraph-strategy.tsv
  printf 'path\tname\n' >"$M"
  printf 'path\tname\tcut.room_width_m\tclean.outlier_percent\n' >"$S"
  for image in "$AG"/input/*.png; do
    name=$(basename "$image" .png)
    w=$(setting "w (m) according" "$name")
    noise=$(setting "noise percentage" "$name")
    printf '%s\tag_%s\n' "$(realpath "$image")" "$name" >>"$M"
    printf '%s\tag_%s\t%s\t%s\n' "$(realpath "$image")" "$name" "${w:-1.25}" "${noise:-1.5}" >>"$S"
  done
  run "$M" "$OUT/areagraph/auto" "${OURS[@]}"
  run "$S" "$OUT/areagraph/strategy"
  run "$S" "$OUT/areagraph/fixed" "${FIXED[@]}"
  run "$M" "$OUT/areagraph/paper" "${PAPER[@]}"
  for dir in "$OUT"/areagraph/*/; do  # results named like the GT
    for f in "$dir"ag_*.png; do [ -e "$f" ] && mv "$f" "$dir$(basename "$f" | sed 's/^ag_//')"; done
  done
  for variant in standard maoris; do
    flags=(--mcc-variant "$variant")
    for run_name in auto strategy fixed paper; do
      mcc "$OUT/areagraph/$run_name" "$AG/GT" "${flags[@]}" >"$T/ag-$run_name-$variant"
    done
    mcc "$AG/strategy_w" "$AG/GT" "${flags[@]}" --drop-result-px 100 >"$T/ag-code-strategy-$variant"
    mcc "$AG/w=1_25" "$AG/GT" "${flags[@]}" --drop-result-px 100 >"$T/ag-code-fixed-$variant"
  done
  summary_row "areagraph/" "$T/ag-auto-maoris" "$T/ag-fixed-maoris" "$T/ag-paper-maoris" \
    "paper code: strategy W $(mean_of "$T/ag-code-strategy-maoris"), W = 1.25 $(mean_of "$T/ag-code-fixed-maoris")"
fi

if wanted robotmap; then
  M=$OUT/manifests/robotmap.tsv
  printf 'path\tname\n' >"$M"
  for image in "$RM"/Maps/*.png; do
    printf '%s\trm_%s\n' "$(realpath "$image")" "$(basename "$image" .png)" >>"$M"
  done
  run "$M" "$OUT/robotmap/auto" "${OURS[@]}"
  run "$M" "$OUT/robotmap/fixed" "${FIXED[@]}"
  run "$M" "$OUT/robotmap/paper" "${PAPER[@]}"
  for dir in "$OUT"/robotmap/*/; do
    for f in "$dir"rm_*.png; do [ -e "$f" ] && mv "$f" "$dir$(basename "$f" | sed 's/^rm_//')"; done
  done
  for variant in standard maoris; do
    flags=(--gt-style maoris-lines --mcc-variant "$variant")
    for run_name in auto fixed paper; do
      mcc "$OUT/robotmap/$run_name" "$RM/GT" "${flags[@]}" >"$T/rm-$run_name-$variant"
    done
    mcc "$RM/maoris/t03m01R40D50" "$RM/GT" "${flags[@]}" >"$T/rm-maoris-$variant"
    mcc "$RM/Voronoi" "$RM/GT" "${flags[@]}" >"$T/rm-voronoi-$variant"
    mcc "$RM/DuDe_results/Incremental" "$RM/GT" "${flags[@]}" >"$T/rm-dude-$variant"
  done
  summary_row "RobotMap" "$T/rm-auto-maoris" "$T/rm-fixed-maoris" "$T/rm-paper-maoris" \
    "MAORIS $(mean_of "$T/rm-maoris-maoris"), DuDe $(mean_of "$T/rm-dude-maoris"), Voronoi $(mean_of "$T/rm-voronoi-maoris")"
fi

BM_VARIANTS=(plain furnitures trashbins furnitures_trashbins)
if wanted bormann; then
  M=$OUT/manifests/bormann.tsv
  printf 'path\tname\timport.resolution_m\n' >"$M"
  for gt in "$BM"/*_gt_segmentation.png; do
    base=$(basename "$gt" _gt_segmentation.png)
    for variant in "${BM_VARIANTS[@]}"; do
      suffix=_$variant
      [ "$variant" = plain ] && suffix=
      image=$BM/$base$suffix.png
      [ -e "$image" ] || continue
      resolution=0.05
      # Published at 649x243 instead of 974x365 like the other variants.
      [ "$base$suffix" = lab_b_scan_furnitures_trashbins ] && resolution=0.075
      printf '%s\tbm_%s__%s\t%s\n' "$(realpath "$image")" "$variant" "$base" "$resolution" >>"$M"
    done
  done
  for run_name in auto fixed paper; do
    case $run_name in auto) flags=("${OURS[@]}") ;; fixed) flags=("${FIXED[@]}") ;;
      paper) flags=("${PAPER[@]}") ;; esac
    run "$M" "$OUT/bormann/$run_name" "${flags[@]}"
    for variant in "${BM_VARIANTS[@]}"; do
      mkdir -p "$OUT/bormann/$run_name-$variant"
      for f in "$OUT/bormann/$run_name"/bm_"$variant"__*.png; do
        [ -e "$f" ] && mv "$f" "$OUT/bormann/$run_name-$variant/$(basename "$f" | sed 's/^bm_.*__//')"
      done
      mcc "$OUT/bormann/$run_name-$variant" "$BM" --gt-suffix _gt_segmentation --gt-style lines \
        --mcc-variant maoris --scale-result >"$T/bm-$run_name-$variant"
    done
    # All 79 maps in one column: map names get the variant.
    for variant in "${BM_VARIANTS[@]}"; do
      grep -vE '^(mean|median)	' "$T/bm-$run_name-$variant" | sed "s/^/$variant: /"
    done | awk -F'\t' '{ print; sum += $2; n++ } END { if (n) printf "mean\t%.3f\n", sum / n }' \
      >"$T/bm-$run_name-all"
  done
  for variant in "${BM_VARIANTS[@]}"; do
    summary_row "bormann/ ${variant//_/ + }" "$T/bm-auto-$variant" "$T/bm-fixed-$variant" \
      "$T/bm-paper-$variant" "-"
  done
  summary_row "bormann/ all variants" "$T/bm-auto-all" "$T/bm-fixed-all" "$T/bm-paper-all" "-"
fi

KINDS=1
for part in $GENERATED; do
  wanted "$part" || continue
  G=$OUT/generated/$part
  "$BIN/ag-make-benchmark" --part "$part" "$G" >/dev/null
  M=$OUT/manifests/$part.tsv
  S=$OUT/manifests/$part-true-widths.tsv
  printf 'path\tname\n' >"$M"
  printf 'path\tname\tcut.room_width_m\n' >"$S"
  # The paper's rule on the drawn widths: door + 0.1 m when the widest door
  # is narrower than the corridor (or there is none), else corridor - 0.1 m.
  tail -n +2 "$G/index.tsv" | while IFS=$'\t' read -r name seed layout res corridor narrow wide zones; do
    printf '%s\t%s\n' "$(realpath "$G/maps/$name.png")" "$name" >>"$M"
    w=$(awk -v d="$wide" -v c="$corridor" 'BEGIN { print (c == 0 || d < c) ? d + 0.1 : c - 0.1 }')
    printf '%s\t%s\t%s\n' "$(realpath "$G/maps/$name.png")" "$name" "$w" >>"$S"
  done
  run "$M" "$OUT/$part/auto" "${OURS[@]}"
  run "$M" "$OUT/$part/fixed" "${FIXED[@]}"
  run "$S" "$OUT/$part/true"
  run "$M" "$OUT/$part/paper" "${PAPER[@]}"
  for run_name in auto fixed true paper; do
    mcc "$OUT/$part/$run_name" "$G/gt" --gt-style labels --mcc-variant maoris >"$T/$part-$run_name"
    if [ -e "$OUT/$part/$run_name.kinds" ]; then
      mv "$OUT/$part/$run_name.kinds" "$T/$part-$run_name-kinds"
    else
      : >"$T/$part-$run_name-kinds"
    fi
  done
  for w in ${WIDTHS//,/ }; do
    [ "$w" = "$FIRST_W" ] && { cp "$T/$part-fixed" "$T/$part-w$w"; continue; }
    run "$M" "$OUT/$part/w$w" --set "cut.room_width_m=$w"
    mcc "$OUT/$part/w$w" "$G/gt" --gt-style labels --mcc-variant maoris >"$T/$part-w$w"
  done
  summary_row "generated $part" "$T/$part-auto" "$T/$part-fixed" "$T/$part-paper" \
    "ours with W from the true widths $(mean_of "$T/$part-true"); kind accuracy $(mean_of "$T/$part-auto-kinds")"
done
KINDS=0

echo "## Segmentation quality, $(date -u +%Y-%m-%d)"
echo
echo "Mean MCC (ag-eval, maoris variant). Defaults: no per-map settings."
echo
echo "| set | maps | ours, defaults | ours, W = $FIRST_W m (no estimated doors closed) | ours, paper options | published / reference |"
echo "|---|---|---|---|---|---|"
cat "$SUMMARY"
if wanted areagraph; then
  for variant in maoris standard; do
    table "areagraph/ (16 maps), MCC ($variant)" \
      "ours, defaults (auto W):$T/ag-auto-$variant" "ours, strategy W:$T/ag-strategy-$variant" \
      "ours, W = 1.25:$T/ag-fixed-$variant" "ours, paper options:$T/ag-paper-$variant" \
      "paper code, strategy W:$T/ag-code-strategy-$variant" \
      "paper code, W = 1.25:$T/ag-code-fixed-$variant"
  done
fi
if wanted robotmap; then
  for variant in maoris standard; do
    table "maoris/RobotMap (20 maps), MCC ($variant)" \
      "ours, defaults:$T/rm-auto-$variant" "ours, W = 1.25:$T/rm-fixed-$variant" \
      "ours, paper options:$T/rm-paper-$variant" "MAORIS:$T/rm-maoris-$variant" \
      "Bormann Voronoi:$T/rm-voronoi-$variant" "DuDe:$T/rm-dude-$variant"
  done
fi
if wanted bormann; then
  table "bormann/ (20 maps x 4 variants), MCC (maoris), ours with the defaults" \
    "plain:$T/bm-auto-plain" "furnitures:$T/bm-auto-furnitures" \
    "trashbins:$T/bm-auto-trashbins" "furnitures + trashbins:$T/bm-auto-furnitures_trashbins"
fi
for part in $GENERATED; do
  wanted "$part" || continue
  table "generated $part ($(count_of "$T/$part-auto") floors), MCC (maoris)" \
    "ours, defaults:$T/$part-auto" "ours, W = $FIRST_W:$T/$part-fixed" \
    "ours, W from true widths:$T/$part-true" "ours, paper options:$T/$part-paper" \
    "kind accuracy, defaults:$T/$part-auto-kinds"
done
if [ "$WIDTHS" != "$FIRST_W" ]; then
  echo
  echo "### Generated sets: mean MCC (maoris) with each fixed W"
  echo
  header="| set | defaults"; rule="|---|---"
  for w in ${WIDTHS//,/ }; do header="$header | W = $w"; rule="$rule|---"; done
  echo "$header |"; echo "$rule|"
  for part in $GENERATED; do
    wanted "$part" || continue
    line="| $part | $(mean_of "$T/$part-auto")"
    for w in ${WIDTHS//,/ }; do line="$line | $(mean_of "$T/$part-w$w")"; done
    echo "$line |"
  done
fi
