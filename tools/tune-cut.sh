#!/usr/bin/env bash
# Chooses cut's constants by script on a declared split, never by looking at
# a named map. Every candidate value of each constant below (the others at
# their defaults) runs through ag-run on every set and is scored with ag-eval
# (maoris MCC, as bench-quality.sh). A constant takes the candidate with the
# best mean, over the parts of a split, of each part's mean MCC; a tie keeps
# the default.
# - The declared tuning split: the generated office floors of
#   `ag-make-benchmark --part tuning`, the public buildings of
#   `--part public-tuning` and MAORIS' 20 RobotMap maps. The generated
#   held-out parts, areagraph/ and bormann/ are only reported.
# - Leave one set out: for each of areagraph/, RobotMap, bormann/ (plain and
#   furnitures), the generated offices (tuning and held-out) and the generated
#   public buildings (public-tuning and public-held-out), the constants are
#   chosen on the other four, and that set is scored with them (a mean of its
#   parts' means).
# Prints the table of every candidate on every part, the values chosen on the
# tuning split as --set flags, and the leave-one-set-out table (Markdown).
#
#   tools/tune-cut.sh [--build DIR] [--out DIR] [--data DIR] [--jobs N]
set -euo pipefail
cd "$(dirname "$0")/.."
OUT=out/tune-cut
DATA=../shared/data
BUILD=
JOBS=2
while [ $# -gt 0 ]; do
  case "$1" in
    --build) BUILD=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    --data) DATA=$2; shift 2 ;;
    --jobs) JOBS=$2; shift 2 ;;
    -h|--help) sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "tune-cut: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
if [ -n "$BUILD" ]; then
  BIN=$BUILD/bin
  [ -x "$BIN/ag-run" ] || { echo "tune-cut: no ag-run in $BIN" >&2; exit 1; }
else
  tools/build.sh >/dev/null
  BIN=build/bin
fi

# The constants and their candidates; the first value of each is its default.
CONSTANTS=(
  "cut.mouths.max_width_m 0 6 10"
  "cut.room_width_open_doors false true"
  "cut.wall_gaps.max_width_m 3.5 3 4"
  "cut.islands.max_length_m 4 3 5"
)
TUNING_PARTS=(tuning public-tuning robotmap)
SETS=(areagraph robotmap bormann offices public)
declare -A SET_PARTS=(
  [areagraph]="areagraph" [robotmap]="robotmap" [bormann]="bormann-plain bormann-furnitures"
  [offices]="tuning held-out" [public]="public-tuning public-held-out"
)
AG=$DATA/areagraph
RM=$DATA/maoris/RobotMap
BM=$DATA/bormann
for dir in "$AG/input" "$RM/Maps" "$BM"; do
  [ -d "$dir" ] || { echo "tune-cut: no maps in $dir (use --data)" >&2; exit 1; }
done

rm -rf "$OUT"
mkdir -p "$OUT/scores"
declare -A GT_FLAGS
manifest() {  # manifest PART IMAGE... (names are the images' base names)
  local part=$1
  shift
  printf 'path\tname\n' >"$OUT/$part.tsv"
  for image in "$@"; do
    printf '%s\t%s\n' "$(realpath "$image")" "$(basename "$image" .png)" >>"$OUT/$part.tsv"
  done
}
for part in tuning held-out public-tuning public-held-out; do
  "$BIN/ag-make-benchmark" --part "$part" "$OUT/generated/$part" >/dev/null
  manifest "$part" "$OUT/generated/$part"/maps/*.png
  GT_FLAGS[$part]="--gt $OUT/generated/$part/gt --gt-style labels"
done
manifest areagraph "$AG"/input/*.png
GT_FLAGS[areagraph]="--gt $AG/GT"
manifest robotmap "$RM"/Maps/*.png
GT_FLAGS[robotmap]="--gt $RM/GT --gt-style maoris-lines"
for variant in plain furnitures; do
  printf 'path\tname\timport.resolution_m\n' >"$OUT/bormann-$variant.tsv"
  for gt in "$BM"/*_gt_segmentation.png; do
    base=$(basename "$gt" _gt_segmentation.png)
    image=$BM/$base.png
    [ "$variant" = plain ] || image=$BM/${base}_$variant.png
    [ -e "$image" ] && printf '%s\t%s\t0.05\n' "$(realpath "$image")" "$base" >>"$OUT/bormann-$variant.tsv"
  done
  GT_FLAGS[bormann-$variant]="--gt $BM --gt-suffix _gt_segmentation --gt-style lines --scale-result"
done

# score PART [--set k=v]... -> the part's mean MCC with those options,
# computed once per part and set of flags.
score() {
  local part=$1
  shift
  local id
  id=$(printf '%s ' "$part" "$@" | md5sum | cut -c1-16)
  if [ ! -e "$OUT/scores/$id" ]; then
    local store=$OUT/$part.db labels=$OUT/labels-$part
    rm -rf "$labels" "$store" "$store-wal" "$store-shm"
    mkdir -p "$labels"
    "$BIN/ag-run" --store "$store" --jobs "$JOBS" "$@" "$OUT/$part.tsv" >"$OUT/$part.log" 2>&1 ||
      true
    tail -n +2 "$OUT/$part.tsv" | cut -f2 | while read -r name; do
      "$BIN/ag-export" --store "$store" --map "$name" --format labels \
        --out "$labels/$name.png" >/dev/null 2>&1 || true
    done
    # shellcheck disable=SC2086 # GT_FLAGS holds several words
    "$BIN/ag-eval" --dataset --results "$labels" ${GT_FLAGS[$part]} --mcc-variant maoris \
      2>/dev/null | awk -F'|' '$2 ~ /mean/ { gsub(/[ *]/, "", $3); print $3 }' >"$OUT/scores/$id"
  fi
  local mean
  mean=$(cat "$OUT/scores/$id")
  echo "${mean:-0}"
}

mean_over() {  # mean_over FLAGS_VAR PART... -> mean of the parts' scores
  local -n flags_ref=$1
  shift
  local sum=0 part
  for part in "$@"; do
    sum=$(awk -v s="$sum" -v m="$(score "$part" "${flags_ref[@]}")" 'BEGIN { print s + m }')
  done
  awk -v s="$sum" -v n=$# 'BEGIN { printf "%.4f", s / n }'
}

ALL_PARTS=(areagraph robotmap bormann-plain bormann-furnitures tuning held-out public-tuning
  public-held-out)
echo "### Every candidate on every part (mean MCC, maoris; the others at their defaults)"
echo
header="| constant = value" rule="|---"
for part in "${ALL_PARTS[@]}"; do header="$header | $part" rule="$rule|---"; done
echo "$header |"
echo "$rule|"
CANDIDATES=()  # "key value" of every non-default candidate
for entry in "${CONSTANTS[@]}"; do
  read -r key default values <<<"$entry"
  for value in $values; do CANDIDATES+=("$key $value"); done
done
# shellcheck disable=SC2034 # read through mean_over's name reference
no_flags=()
line="| defaults"
for part in "${ALL_PARTS[@]}"; do line="$line | $(score "$part")"; done
echo "$line |"
for candidate in "${CANDIDATES[@]}"; do
  read -r key value <<<"$candidate"
  flags=(--set "$key=$value")
  line="| $key = $value"
  for part in "${ALL_PARTS[@]}"; do line="$line | $(score "$part" "${flags[@]}")"; done
  echo "$line |"
done

# choose PART... -> "--set key=value" lines for the non-default choices on PARTS
choose() {
  local entry key default values value best best_score flags total
  for entry in "${CONSTANTS[@]}"; do
    read -r key default values <<<"$entry"
    best=$default
    best_score=$(mean_over no_flags "$@")
    for value in $values; do
      flags=(--set "$key=$value")
      total=$(mean_over flags "$@")
      if awk -v t="$total" -v b="$best_score" 'BEGIN { exit !(t > b) }'; then
        best=$value best_score=$total
      fi
    done
    [ "$best" = "$default" ] || echo "--set $key=$best"
  done
}

echo
echo "### Chosen on the tuning split (${TUNING_PARTS[*]})"
echo
chosen=$(choose "${TUNING_PARTS[@]}")
echo "${chosen:-(the defaults)}"
echo
echo "### Leave one set out (each set scored with constants chosen on the other four)"
echo
echo "| set | chosen without it | defaults | with the chosen constants |"
echo "|---|---|---|---|"
for group in "${SETS[@]}"; do
  others=()
  for other in "${SETS[@]}"; do
    # shellcheck disable=SC2206 # SET_PARTS holds several words
    [ "$other" = "$group" ] || others+=(${SET_PARTS[$other]})
  done
  mapfile -t chosen < <(choose "${others[@]}")
  flags=()
  for choice in "${chosen[@]}"; do read -r _ kv <<<"$choice" && flags+=(--set "$kv"); done
  # shellcheck disable=SC2086 # SET_PARTS holds several words
  printf '| %s | %s | %s | %s |\n' "$group" "${chosen[*]:-(the defaults)}" \
    "$(mean_over no_flags ${SET_PARTS[$group]})" "$(mean_over flags ${SET_PARTS[$group]})"
done
