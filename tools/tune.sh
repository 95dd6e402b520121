#!/usr/bin/env bash
# Chooses the segmentation's constants by script on a declared split, never
# by looking at a named map. Each candidate of tools/tune-candidates.txt
# (the others at their defaults) runs through ag-run on every part and is
# scored with ag-eval (maoris MCC, as bench-quality.sh). An option's
# candidate is a --set flag; a named constant's candidate is a build of a
# copy of the source with that one value changed. A constant takes the
# candidate with the best mean, over the parts of a split, of each part's
# mean MCC; a tie keeps the default.
# - The declared tuning split: the generated office floors of
#   `ag-make-benchmark --part tuning`, the public buildings of
#   `--part public-tuning` and MAORIS' 20 RobotMap maps. The generated
#   held-out parts, areagraph/ and bormann/ are only reported.
# - Leave one set out: for each of areagraph/, RobotMap, bormann/ (plain and
#   furnitures), the generated offices (tuning and held-out) and the generated
#   public buildings (public-tuning and public-held-out), the constants are
#   chosen on the other four, and that set is scored with them (a mean of its
#   parts' means).
# Prints the table of every candidate on every part, each constant's mean
# over the tuning split for each of its values, the values chosen there, and
# the leave-one-set-out table (Markdown).
#
#   tools/tune.sh [--only REGEX] [--build DIR] [--out DIR] [--data DIR] [--jobs N]
#                 [--candidates FILE] [--no-loso]
#   tools/tune.sh --check [--build DIR] [--candidates FILE]
#
# --only: tune only the candidates whose name matches REGEX (grep -E), e.g.
# '^cut\.' or 'furniture_rows'. --check: only checks the candidates file
# against the source and the options (each constant's declaration holds its
# default, ag-run accepts each option candidate) and that every tunable
# constant of tools/count-tunables.sh has candidates; prints their count.
# --no-loso: stop before the leave-one-set-out table (its choices need runs,
# and builds, of their own). --candidates: another candidates file than
# tools/tune-candidates.txt. The first constant candidate builds a copy of
# the source under --out (keep it inside the checkout's parent so that
# ccache hits: minutes without).
set -euo pipefail
shopt -s inherit_errexit  # a failed score inside $(...) stops the script
cd "$(dirname "$0")/.."
OUT=out/tune
DATA=../shared/data
BUILD=
JOBS=2
ONLY=.
CHECK=0
LOSO=1
CANDIDATES_FILE=tools/tune-candidates.txt
while [ $# -gt 0 ]; do
  case "$1" in
    --only) ONLY=$2; shift 2 ;;
    --build) BUILD=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    --data) DATA=$2; shift 2 ;;
    --jobs) JOBS=$2; shift 2 ;;
    --check) CHECK=1; shift ;;
    --no-loso) LOSO=0; shift ;;
    --candidates) CANDIDATES_FILE=$2; shift 2 ;;
    -h|--help) awk 'NR > 1 && !/^#/ { exit } NR > 1' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "tune: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
if [ -n "$BUILD" ]; then
  BIN=$BUILD/bin
  [ -x "$BIN/ag-run" ] || { echo "tune: no ag-run in $BIN" >&2; exit 1; }
else
  tools/build.sh ag-run ag-export ag-eval ag-make-benchmark >/dev/null
  BIN=build/bin
fi

[ -r "$CANDIDATES_FILE" ] || { echo "tune: cannot read $CANDIDATES_FILE" >&2; exit 1; }
# ENTRIES: "option KEY DEFAULT VALUE..." or "constant FILE NAME DEFAULT VALUE..."
mapfile -t ENTRIES < <(grep -Ev '^[[:space:]]*(#|$)' "$CANDIDATES_FILE")

entry_name() {  # the name --only matches: the option key, or FILE:NAME
  local kind file name
  read -r kind file name _ <<<"$1"
  if [ "$kind" = option ]; then echo "$file"; else echo "$file:$name"; fi
}

# declared_value FILE NAME -> the literal the declaration of NAME assigns
# (`kName = 4.0` or a Params field `name = 4.0`); fails unless exactly one.
declared_value() {
  local file=$1 field=${2##*::}
  local values
  values=$(grep -oE "\\b$field\\b[[:space:]]*=[[:space:]]*[-0-9.eE]+" "$file" |
    sed -E 's/.*=[[:space:]]*//') || true
  [ -n "$values" ] && [ "$(wc -l <<<"$values")" -eq 1 ] || return 1
  echo "$values"
}

same_number() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a + 0 == b + 0) }'; }

check() {
  local entry kind file name default values value declared status=0 count=0
  for entry in "${ENTRIES[@]}"; do
    read -r kind file name default values <<<"$entry"
    case "$kind" in
      constant)
        if ! declared=$(declared_value "$file" "$name"); then
          echo "tune: $file declares $name not exactly once" >&2
          status=1
        elif ! same_number "$declared" "$default"; then
          echo "tune: $file has $name = $declared, the candidates file says $default" >&2
          status=1
        fi ;;
      option)
        # An option entry is "option KEY DEFAULT VALUE...": shift the fields.
        values="$default $values" default=$name name=$file
        for value in $default $values; do
          "$BIN/ag-run" --print-options --set "$name=$value" >/dev/null 2>&1 || {
            echo "tune: ag-run refuses --set $name=$value" >&2
            status=1
          }
        done ;;
      *) echo "tune: unknown kind '$kind' in $CANDIDATES_FILE" >&2; status=1 ;;
    esac
    count=$((count + 1))
  done
  local listed missing
  listed=$(for entry in "${ENTRIES[@]}"; do entry_name "$entry"; done)
  missing=$(tools/count-tunables.sh | awk -F'\t' '$1 == "constant" && $4 == "tunable" {
      split($2, at, ":"); name = $3; sub(/ = .*/, "", name); sub(/.*::/, "", name)
      print at[1] ":" name }' | grep -vxF -f <(sed -E 's/:[^:]*::/:/' <<<"$listed") || true)
  if [ -n "$missing" ]; then
    echo "tune: tunable constants without candidates: $(tr '\n' ' ' <<<"$missing")" >&2
    status=1
  fi
  [ "$status" -eq 0 ] && echo "tune: $count candidates checked"
  return "$status"
}
if [ "$CHECK" -eq 1 ]; then
  check
  exit
fi
check >/dev/null

for dir in "$DATA/areagraph/input" "$DATA/maoris/RobotMap/Maps" "$DATA/bormann"; do
  [ -d "$dir" ] || { echo "tune: no maps in $dir (use --data)" >&2; exit 1; }
done

ALL_PARTS=(areagraph robotmap bormann-plain bormann-furnished tuning held-out public-tuning
  public-held-out)
mkdir -p "$OUT/scores" "$OUT/bins"
# shellcheck source=tools/bench-sets.sh
source tools/bench-sets.sh
for part in "${ALL_PARTS[@]}"; do set_manifest "$part"; done

# A configuration is a list of changes "ENTRY=VALUE" (ENTRY a candidates
# file line): options become --set flags, constants a build of a copy of the
# source in which only those declarations differ. The copy's build tree is
# shared, so each build recompiles only what includes a changed file.
config_bin() {  # config_bin CHANGE... -> the bin directory for its constants
  local change entry value kind file name patches=()
  for change in "$@"; do
    entry=${change%=*} value=${change##*=}
    read -r kind file name _ <<<"$entry"
    [ "$kind" = constant ] && patches+=("$file $name $value")
  done
  [ ${#patches[@]} -gt 0 ] || { echo "$BIN"; return; }
  local bins
  bins=$OUT/bins/$(printf '%s\n' "${patches[@]}" | md5sum | cut -c1-16)
  if [ ! -x "$bins/ag-run" ]; then
    if [ ! -d "$OUT/src" ]; then
      mkdir -p "$OUT/src"
      git ls-files -z --cached --others --exclude-standard |
        tar --null -T - --ignore-failed-read -cf - 2>/dev/null | tar -xf - -C "$OUT/src"
      cmake -S "$OUT/src" -B "$OUT/variant-build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
    fi
    local patch field
    for patch in "${patches[@]}"; do
      read -r file name value <<<"$patch"
      field=${name##*::}
      sed -E -i "s/(\\b$field\\b[[:space:]]*=[[:space:]]*)[-0-9.eE]+/\\1$value/" "$OUT/src/$file"
    done
    echo "tune: building ${patches[*]}" >&2
    cmake --build "$OUT/variant-build" -j "$JOBS" --target ag-run ag-export ag-eval >/dev/null
    for patch in "${patches[@]}"; do
      read -r file _ <<<"$patch"
      cp "$file" "$OUT/src/$file"
    done
    mkdir -p "$bins"
    cp "$OUT/variant-build/bin/"{ag-run,ag-export,ag-eval} "$OUT/variant-build/bin/"*.so "$bins/"
  fi
  echo "$bins"
}

config_flags() {  # config_flags CHANGE... -> the --set flags, one per line
  local change entry value kind key
  for change in "$@"; do
    entry=${change%=*} value=${change##*=}
    read -r kind key _ <<<"$entry"
    [ "$kind" = option ] && printf -- '--set\n%s=%s\n' "$key" "$value"
  done
  return 0
}

# Whether no change can alter the stages before cut: options of cut, merge
# and match, and constants of their folders that no earlier stage's folder
# (nor geometry's or common's) includes. Such runs start from the part's
# upstream store and compute only cut, merge and match.
upstream_unchanged() {
  local change kind key
  for change in "$@"; do
    read -r kind key _ <<<"${change%=*}"
    case "$kind:$key" in
      option:cut.* | option:merge.* | option:match.*) ;;
      constant:stages/cut/* | constant:stages/merge/* | constant:stages/match/*)
        if grep -rqF "\"$key\"" stages/import stages/clean stages/voronoi stages/prune \
          stages/geometry stages/common; then
          return 1
        fi ;;
      *) return 1 ;;
    esac
  done
}

# score PART CHANGE... -> the part's mean MCC with those changes, computed
# once per part and configuration.
score() {
  local part=$1
  shift
  local bin flags id
  bin=$(config_bin "$@")
  mapfile -t flags < <(config_flags "$@")
  id=$(printf '%s ' "$part" "$bin" "${flags[@]}" | md5sum | cut -c1-16)
  if [ ! -e "$OUT/scores/$id" ]; then
    echo "tune: scoring $part ${flags[*]} ($bin)" >&2
    local seed=
    if upstream_unchanged "$@"; then seed=$(upstream_store "$part" "$BIN"); fi
    # Written aside and renamed: a run stopped halfway leaves no score behind.
    SEED_STORE=$seed score_part "$part" "$OUT/labels-$part" "$bin" "${flags[@]}" \
      >"$OUT/scores/$id.part"
    mv "$OUT/scores/$id.part" "$OUT/scores/$id"
  fi
  local mean
  mean=$(cat "$OUT/scores/$id")
  if [ -z "$mean" ]; then
    rm -f "$OUT/scores/$id"
    echo "tune: no score for $part with ${flags[*]} ($bin); see $OUT/labels-$part.log" >&2
    exit 1
  fi
  echo "$mean"
}

mean_over() {  # mean_over CHANGES_VAR PART... -> mean of the parts' scores
  local -n changes_ref=$1
  shift
  local sum=0 part part_score
  for part in "$@"; do
    part_score=$(score "$part" "${changes_ref[@]}")
    sum=$(awk -v s="$sum" -v m="$part_score" 'BEGIN { print s + m }')
  done
  awk -v s="$sum" -v n=$# 'BEGIN { printf "%.4f", s / n }'
}

# The selected entries, and their non-default values.
SELECTED=()
for entry in "${ENTRIES[@]}"; do
  entry_name "$entry" | grep -qE "$ONLY" && SELECTED+=("$entry")
done
[ ${#SELECTED[@]} -gt 0 ] || { echo "tune: no candidates match '$ONLY'" >&2; exit 2; }
candidate_values() {  # the entry's non-default values
  local kind default values
  read -r kind _ _ default values <<<"$1"
  if [ "$kind" = option ]; then echo "$default $values"; else echo "$values"; fi
}

TUNING_PARTS=(tuning public-tuning robotmap)
SETS=(areagraph robotmap bormann offices public)
declare -A SET_PARTS=(
  [areagraph]="areagraph" [robotmap]="robotmap" [bormann]="bormann-plain bormann-furnished"
  [offices]="tuning held-out" [public]="public-tuning public-held-out"
)

echo "### Every candidate on every part (mean MCC, maoris; the others at their defaults)"
echo
header="| candidate" rule="|---"
for part in "${ALL_PARTS[@]}"; do header="$header | $part" rule="$rule|---"; done
echo "$header |"
echo "$rule|"
# shellcheck disable=SC2034 # read through mean_over's name reference
no_changes=()
line="| defaults"
for part in "${ALL_PARTS[@]}"; do line="$line | $(score "$part")"; done
echo "$line |"
for entry in "${SELECTED[@]}"; do
  for value in $(candidate_values "$entry"); do
    line="| $(entry_name "$entry") = $value"
    for part in "${ALL_PARTS[@]}"; do line="$line | $(score "$part" "$entry=$value")"; done
    echo "$line |"
  done
done

# choose PART... -> a "ENTRY=VALUE" line for each non-default choice on PARTS
choose() {
  local entry best best_score value total candidate
  best_score=$(mean_over no_changes "$@")
  for entry in "${SELECTED[@]}"; do
    best=
    local top=$best_score
    for value in $(candidate_values "$entry"); do
      # shellcheck disable=SC2034 # read through mean_over's name reference
      candidate=("$entry=$value")
      total=$(mean_over candidate "$@")
      if awk -v t="$total" -v b="$top" 'BEGIN { exit !(t > b) }'; then
        best=$value top=$total
      fi
    done
    [ -z "$best" ] || echo "$entry=$best"
  done
}
describe() {  # describe CHANGE... -> "name = value; ..."
  local change out=()
  for change in "$@"; do out+=("$(entry_name "${change%=*}") = ${change##*=}"); done
  local IFS=';'
  echo "${out[*]:-(the defaults)}"
}

echo
echo "### Each constant on the tuning split (${TUNING_PARTS[*]}: the mean of the parts' means)"
echo
echo "| constant | default | other values | chosen |"
echo "|---|---|---|---|"
mapfile -t chosen < <(choose "${TUNING_PARTS[@]}")
default_mean=$(mean_over no_changes "${TUNING_PARTS[@]}")
for entry in "${SELECTED[@]}"; do
  read -r kind _ _ default _ <<<"$entry"
  [ "$kind" = option ] && read -r _ _ default _ <<<"$entry"
  others=() pick=$default
  for value in $(candidate_values "$entry"); do
    # shellcheck disable=SC2034 # read through mean_over's name reference
    candidate=("$entry=$value")
    others+=("$value: $(mean_over candidate "${TUNING_PARTS[@]}")")
  done
  for change in "${chosen[@]}"; do [ "${change%=*}" = "$entry" ] && pick=${change##*=}; done
  printf '| %s | %s: %s | %s | %s |\n' "$(entry_name "$entry")" "$default" "$default_mean" \
    "$(IFS=';'; echo "${others[*]}" | sed 's/;/; /g')" "$pick"
done
echo
echo "### Chosen on the tuning split (${TUNING_PARTS[*]})"
echo
describe "${chosen[@]}"
[ "$LOSO" -eq 1 ] || exit 0
echo
echo "### Leave one set out (each set scored with the constants chosen on the other four)"
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
  # shellcheck disable=SC2086 # SET_PARTS holds several words
  printf '| %s | %s | %s | %s |\n' "$group" "$(describe "${chosen[@]}")" \
    "$(mean_over no_changes ${SET_PARTS[$group]})" "$(mean_over chosen ${SET_PARTS[$group]})"
done
