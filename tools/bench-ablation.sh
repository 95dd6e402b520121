#!/usr/bin/env bash
# Ablation of the quality options beyond the paper: runs the Area Graph
# paper's 16 maps, MAORIS' 20 RobotMap maps and the 30 generated tuning
# floors (no per-map settings) from examples/options/paper.pbtxt, adding one
# improvement per step in the order they were built, and prints one Markdown
# table of mean MCC (ag-eval, MAORIS' variant). The last step must equal the
# defaults: the script checks that a defaults run after it is a cache hit
# for every stage, and fails otherwise.
#
#   tools/bench-ablation.sh [--data DIR] [--out DIR] [--build DIR] [--sets LIST]
#   tools/bench-ablation.sh --check [--build DIR]
#
# --sets: comma-separated subset of areagraph,robotmap,tuning (default: all).
# --check: only the last check, on examples/office_small.png (a second): a
# rule that the defaults turn on must be a step here (the test suite runs it).
set -euo pipefail
cd "$(dirname "$0")/.."
DATA=../shared/data
OUT=out/bench-ablation
BUILD=
SETS=areagraph,robotmap,tuning
CHECK=0
while [ $# -gt 0 ]; do
  case "$1" in
    --data) DATA=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    --build) BUILD=$2; shift 2 ;;
    --sets) SETS=$2; shift 2 ;;
    --check) CHECK=1; shift ;;
    -h|--help) sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "bench-ablation: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
if [ -n "$BUILD" ]; then BIN=$BUILD/bin; else tools/build.sh >/dev/null; BIN=build/bin; fi

# One step per rule, in the order they were built (docs/quality.md, "Options beyond
# the paper", says what each does); each step keeps the assignments of the steps before it.
STEPS=(
  "paper (examples/options/paper.pbtxt)|"
  "+ 2026-11-21 options (unknown islands, min area, growth gap, freed cells out)|clean.unknown_island_max_m2=0.25 merge.min_area_m2=4 merge.grow_min_gap_m=0.5 merge.cover_removed_obstacles=false"
  "+ cut.room_width_auto (the paper's rule on measured widths)|cut.room_width_auto=true"
  "+ cut.room_width_above_doors|cut.room_width_above_doors=true"
  "+ prune.min_clearance_m 0.15|prune.min_clearance_m=0.15"
  "+ merge.join_corridor_pieces|merge.join_corridor_pieces=true"
  "+ merge.fold_open_bays|merge.fold_open_bays=true"
  "+ prune.min_component_m2 4|prune.min_component_m2=4"
  "+ merge.outline_tolerance_m 0.1 and merge.min_hole_m2 0.05|merge.outline_tolerance_m=0.1 merge.min_hole_m2=0.05"
  "+ cut.room_island_max_m 4 and merge.join_rooms_without_doors|cut.room_island_max_m=4 merge.join_rooms_without_doors=true"
  "+ cut.close_wall_doors|cut.close_wall_doors=true"
  "+ merge.join_furniture_gaps and merge.label_corridors_by_shape|merge.join_furniture_gaps=true merge.label_corridors_by_shape=true"
  "+ cut.close_wall_gaps_max_m 3.5|cut.close_wall_gaps_max_m=3.5"
  "+ merge.keep_closed_doors|merge.keep_closed_doors=true"
  "+ cut.island_end_on_face|cut.island_end_on_face=true"
  "+ cut.close_wall_gaps_short_tips|cut.close_wall_gaps_short_tips=true"
  "+ merge.fill_furniture_outlines_m 4|merge.fill_furniture_outlines_m=4"
  "+ merge.wall_furniture_islands and merge.join_corridor_clutter|merge.wall_furniture_islands=true merge.join_corridor_clutter=true"
  "+ merge.fold_corridor_pieces_below_m2 20|merge.fold_corridor_pieces_below_m2=20"
  "+ prune.keep_groups_above_m 20|prune.keep_groups_above_m=20"
  "+ merge.join_porous_borders_gap_m 0.5|merge.join_porous_borders_gap_m=0.5"
  "+ merge.join_split_corridors|merge.join_split_corridors=true"
  "+ merge.furniture_max_elongation 5|merge.furniture_max_elongation=5"
  "+ clean.keep_wall_pieces|clean.keep_wall_pieces=true"
  "+ merge.join_one_sided_narrowings|merge.join_one_sided_narrowings=true"
  "+ merge.join_split_corridor_chains|merge.join_split_corridor_chains=true"
  "+ merge.join_corridor_stems|merge.join_corridor_stems=true"
  "+ cut.keep_closed_room_tips|cut.keep_closed_room_tips=true"
  "+ merge.keep_small_closed_rooms|merge.keep_small_closed_rooms=true"
  "+ merge.closed_room_pocket_jamb_m 0.6|merge.closed_room_pocket_jamb_m=0.6"
  "+ cut.cut_narrow_tails and merge.corridor_stems_max_width_m 4|cut.cut_narrow_tails=true merge.corridor_stems_max_width_m=4"
  "+ cut.island_wall_piece_both_ends|cut.island_wall_piece_both_ends=true"
  "+ cut.jamb_wall_behind_line (= defaults)|cut.jamb_wall_behind_line=true"
)

set_flags=()
for entry in "${STEPS[@]}"; do
  for assignment in ${entry#*|}; do set_flags+=(--set "$assignment"); done
done

# expect_defaults STORE MAP: the defaults after the last step's options must
# hit the cache at every stage (the cache key holds the canonical options).
expect_defaults() {
  local store=$1 map=$2 log
  "$BIN/ag-pipeline" --store "$store" --map "$map" --options examples/options/paper.pbtxt \
    "${set_flags[@]}" >/dev/null
  log=$("$BIN/ag-pipeline" --store "$store" --map "$map")
  if grep -q ' computed ' <<<"$log"; then
    echo "bench-ablation: the last step differs from the defaults ($(grep ' computed ' <<<"$log" |
      head -n 1 | awk '{ print $4 }') recomputed): add the new rule as a step" >&2
    exit 1
  fi
}

if [ "$CHECK" = 1 ]; then
  T=$(mktemp -d)
  trap 'rm -rf "$T"' EXIT
  "$BIN/ag-import" --store "$T/s.db" --name office examples/office_small.png >/dev/null
  expect_defaults "$T/s.db" office
  echo "bench-ablation: the last of ${#STEPS[@]} steps equals the defaults"
  exit 0
fi

wanted() { [[ ",$SETS," == *",$1,"* ]]; }
AG=$DATA/areagraph
RM=$DATA/maoris/RobotMap
[ -d "$AG/input" ] || { echo "bench-ablation: no data at $AG/input (use --data)" >&2; exit 1; }
rm -rf "$OUT"
mkdir -p "$OUT"
STORE=$OUT/store.db
images=()
wanted areagraph && images+=("$AG"/input/*.png)
wanted robotmap && images+=("$RM"/Maps/*.png)
if wanted tuning; then
  "$BIN/ag-make-benchmark" --part tuning "$OUT/generated" >/dev/null
  images+=("$OUT"/generated/maps/*.png)
fi

mean_mcc() {  # mean_mcc DIR GT [ag-eval flags] -> mean MCC
  local dir=$1 gt=$2
  shift 2
  { "$BIN/ag-eval" --dataset --results "$dir" --gt "$gt" --mcc-variant maoris "$@" 2>/dev/null ||
      true; } | awk -F'|' '/\*\*mean\*\*/ { gsub(/[ *]/, "", $3); print $3 }'
}

header="| step |"
rule="|---|"
for set in areagraph robotmap tuning; do
  wanted "$set" || continue
  header+=" $set |"
  rule+="---|"
done
echo "Mean MCC (maoris), $(date -u +%Y-%m-%d), one run; each step adds its options to those above."
echo
echo "$header"
echo "$rule"
sets=()
step=0
for entry in "${STEPS[@]}"; do
  title=${entry%%|*}
  for assignment in ${entry#*|}; do sets+=(--set "$assignment"); done
  dir=$OUT/step$step
  mkdir -p "$dir/areagraph" "$dir/robotmap" "$dir/tuning"
  for image in "${images[@]}"; do
    name=$(basename "$image" .png)
    case "$image" in
      "$AG"/*) sub=areagraph ;;
      "$RM"/*) sub=robotmap ;;
      *) sub=tuning ;;
    esac
    map=${sub}_$name
    "$BIN/ag-import" --store "$STORE" --name "$map" "$image" >/dev/null 2>&1
    if "$BIN/ag-pipeline" --store "$STORE" --map "$map" --options examples/options/paper.pbtxt \
        "${sets[@]}" >"$dir/$sub/$name.log" 2>&1; then
      "$BIN/ag-export" --store "$STORE" --map "$map" --format labels --out "$dir/$sub/$name.png" >/dev/null
    else
      echo "bench-ablation: $map failed: $(tail -n 1 "$dir/$sub/$name.log")" >&2
    fi
  done
  row="| $title |"
  wanted areagraph && row+=" $(mean_mcc "$dir/areagraph" "$AG/GT") |"
  wanted robotmap && row+=" $(mean_mcc "$dir/robotmap" "$RM/GT" --gt-style maoris-lines) |"
  wanted tuning && row+=" $(mean_mcc "$dir/tuning" "$OUT/generated/gt" --gt-style labels) |"
  echo "$row"
  step=$((step + 1))
done
first=$(basename "${images[0]}" .png)
case "${images[0]}" in "$AG"/*) first=areagraph_$first ;; "$RM"/*) first=robotmap_$first ;; *) first=tuning_$first ;; esac
expect_defaults "$STORE" "$first"
