#!/usr/bin/env bash
# Ablation of the quality options beyond the paper: runs both benchmark
# datasets (the Area Graph paper's 16 maps and MAORIS' 20 RobotMap maps, no
# per-map settings) from examples/options/paper.pbtxt, adding one improvement
# per step, and prints one Markdown table of mean MCC (ag-eval, MAORIS'
# variant and the standard one). The last step must equal the defaults.
#
#   tools/bench-ablation.sh [--data DIR] [--out DIR] [--build DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
DATA=../shared/data
OUT=out/bench-ablation
BUILD=
while [ $# -gt 0 ]; do
  case "$1" in
    --data) DATA=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    --build) BUILD=$2; shift 2 ;;
    -h|--help) sed -n '2,8p' "$0"; exit 0 ;;
    *) echo "bench-ablation: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
AG=$DATA/areagraph
RM=$DATA/maoris/RobotMap
[ -d "$AG/input" ] || { echo "bench-ablation: no data at $AG/input (use --data)" >&2; exit 1; }
if [ -n "$BUILD" ]; then BIN=$BUILD/bin; else tools/build.sh >/dev/null; BIN=build/bin; fi
rm -rf "$OUT"
mkdir -p "$OUT"
STORE=$OUT/store.db

STEPS=(
  "paper (examples/options/paper.pbtxt)|"
  "+ 2026-11-21 options (unknown islands, min area, growth gap, freed cells out)|clean.unknown_island_max_m2=0.25 merge.min_area_m2=4 merge.grow_min_gap_m=0.5 merge.cover_removed_obstacles=false"
  "+ cut.room_width_m=auto (paper's rule)|cut.room_width_m=auto"
  "+ cut.room_width_above_doors|cut.room_width_above_doors=true"
  "+ prune.min_clearance_m=0.15|prune.min_clearance_m=0.15"
  "+ merge.join_corridor_pieces|merge.join_corridor_pieces=true"
  "+ merge.fold_open_bays (= defaults)|merge.fold_open_bays=true"
)

mean_mcc() {  # mean_mcc DIR GT [ag-eval flags] -> mean MCC
  local dir=$1 gt=$2
  shift 2
  { "$BIN/ag-eval" --dataset --results "$dir" --gt "$gt" "$@" 2>/dev/null || true; } |
    awk -F'|' '/\*\*mean\*\*/ { gsub(/[ *]/, "", $3); print $3 }'
}

echo "| step | areagraph/ maoris | areagraph/ standard | RobotMap maoris | RobotMap standard |"
echo "|---|---|---|---|---|"
sets=()
step=0
for entry in "${STEPS[@]}"; do
  title=${entry%%|*}
  for assignment in ${entry#*|}; do sets+=(--set "$assignment"); done
  dir=$OUT/step$step
  mkdir -p "$dir/ag" "$dir/rm"
  for image in "$AG"/input/*.png "$RM"/Maps/*.png; do
    name=$(basename "$image" .png)
    case "$image" in "$AG"/*) sub=ag; map=ag_$name ;; *) sub=rm; map=rm_$name ;; esac
    "$BIN/ag-import" --store "$STORE" --name "$map" "$image" >/dev/null 2>&1
    if "$BIN/ag-pipeline" --store "$STORE" --map "$map" --options examples/options/paper.pbtxt \
        "${sets[@]}" >"$dir/$sub/$name.log" 2>&1; then
      "$BIN/ag-export" --store "$STORE" --map "$map" --format labels --out "$dir/$sub/$name.png" >/dev/null
    else
      echo "bench-ablation: $map failed: $(tail -n 1 "$dir/$sub/$name.log")" >&2
    fi
  done
  rm_flags=(--gt-style maoris-lines)
  echo "| $title | $(mean_mcc "$dir/ag" "$AG/GT" --mcc-variant maoris) |" \
       "$(mean_mcc "$dir/ag" "$AG/GT" --mcc-variant standard) |" \
       "$(mean_mcc "$dir/rm" "$RM/GT" "${rm_flags[@]}" --mcc-variant maoris) |" \
       "$(mean_mcc "$dir/rm" "$RM/GT" "${rm_flags[@]}" --mcc-variant standard) |"
  step=$((step + 1))
done
