#!/usr/bin/env bash
# Replays the simulated exploration of tools/bench-live.sh through ag-match
# alone (ag-bench-match: the stages up to merge once per update, then match
# under each variant) on the TUNING maps: real maps with ground truth other
# than freiburg_building79 (and its furnished twin) and lab_e, the report
# maps. Match's constants are chosen here (docs/performance.md, "Match's
# constants"); tools/bench-live.sh then reports the report maps. Prints one
# Markdown row per map and variant; a benchmark: it checks nothing.
#
# Usage: tools/bench-match-tuning.sh [--no-build] [--build-dir DIR] [--data DIR]
#          [--cache DIR] [--variant TEXT]... [--report-maps]
#   --variant      match options in text format (repeat; default: the defaults,
#                  neither folding nor join splitting, folding alone)
#   --report-maps  the report maps instead (freiburg_building79, lab_e)
set -euo pipefail
cd "$(dirname "$0")/.."
bench_name=bench-match-tuning
bench_help_lines=2,14
source tools/bench-common.sh
data=../shared/data
cache=""
report=0
variants=()
while [ $# -gt 0 ]; do
  case "$1" in
    --data) data="$2"; shift 2 ;;
    --cache) cache="$2"; shift 2 ;;
    --variant) variants+=(--variant "$2"); shift 2 ;;
    --report-maps) report=1; shift ;;
    *) bench_option "$@"; shift "$bench_shift" ;;
  esac
done
bench_prepare ag-bench-match
[ -n "$cache" ] || cache="$work/cache"
if [ ${#variants[@]} -eq 0 ]; then
  variants=(--variant "" --variant "fold_fragments_below_m2: 0 split_joins_below_m2: 0"
    --variant "split_joins_below_m2: 0")
fi
a=$data/areagraph
r=$data/maoris/RobotMap
if [ "$report" = 1 ]; then
  maps=("freiburg_building79|$data/bormann/freiburg_building79.png|$a/GT/freiburg_building79.png"
    "lab_e|$a/input/lab_e.png|$a/GT/lab_e.png")
else
  maps=()
  for m in lab_c lab_d lab_d_scan_furnitures freiburg_building52 intel_map sistD lab_ipa_furnitures \
    Freiburg101_scan; do
    maps+=("$m|$a/input/$m.png|$a/GT/$m.png")
  done
  for m in office_a office_b office_c office_d office_e office_f office_h NLB lab_f_scan lab_intel; do
    maps+=("robotmap_$m|$r/Maps/$m.png|$r/GT/$m.png")
  done
fi

echo "### ag-match variants on simulated explorations, $(date -u +%Y-%m-%d)"
echo
echo "| map | match options | GT-tracked areas kept, exploration | noise-only | exploration, same-room test | noise-only, same-room test | MCC last | MCC mean | areas last |"
echo "|---|---|---|---|---|---|---|---|---|"
for entry in "${maps[@]}"; do
  IFS='|' read -r name map gt <<<"$entry"
  say "$name"
  "$bin/ag-bench-match" --name "$name" --map "$map" --gt "$gt" --cache "$cache" "${variants[@]}" \
    2>>"$work/bench-match.err"
done
