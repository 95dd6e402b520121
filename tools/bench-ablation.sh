#!/usr/bin/env bash
# Ablation of the passes beyond the paper (clean's, cut's, merge's and
# match's pass tables): every set runs with the defaults, then once per pass
# with that pass skipped (STAGE.skip_passes), and one Markdown table prints
# each set's mean MCC (ag-eval, MAORIS' variant) with the defaults and each
# pass's effect (its set's mean without the pass minus the defaults'). A pass
# that moves no set by 0.005 has to earn its place on a constructed case. The
# passes are the ones that examples/options/paper.pbtxt skips, all of them
# (cut_passes_test and merge_passes_test hold those lists to the tables).
# Match's passes change only how ids survive from one version of a map to the
# next, so a single run of a set shows none of their effect (0.000). The sets
# as tools/bench-quality.sh runs them: areagraph/ (16 maps), RobotMap (20),
# bormann/ plain and furnished (20 each), and the generated tuning and
# held-out floors (30 each). Every run has a new store: match undoes joins
# against a map's earlier Area Graph, so a store kept across the runs would
# let one run's result change the next one's. The runs that change only cut,
# merge or match start from a copy of the set's store of the first four stages.
#
#   tools/bench-ablation.sh [--data DIR] [--out DIR] [--build DIR] [--sets LIST]
#                           [--passes LIST] [--jobs N]
#   tools/bench-ablation.sh --check [--build DIR]
#
# --sets: comma-separated subset of areagraph,robotmap,bormann-plain,
# bormann-furnished,tuning,held-out (default: all). --passes: a subset of the
# passes, each STAGE.PASS or just PASS (e.g. cut.CLOSE_WALL_DOORS or
# JOIN_ROOMS_WITHOUT_DOORS; default: all; none: the defaults row only, e.g. to
# score another build's binaries with --build). --check: only checks that the
# passes named in paper.pbtxt are accepted by ag-run (the test suite runs it).
set -euo pipefail
cd "$(dirname "$0")/.."
DATA=../shared/data
OUT=out/bench-ablation
BUILD=
SETS=areagraph,robotmap,bormann-plain,bormann-furnished,tuning,held-out
PASSES=
JOBS=2
CHECK=0
while [ $# -gt 0 ]; do
  case "$1" in
    --data) DATA=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    --build) BUILD=$2; shift 2 ;;
    --sets) SETS=$2; shift 2 ;;
    --passes) PASSES=$2; shift 2 ;;
    --jobs) JOBS=$2; shift 2 ;;
    --check) CHECK=1; shift ;;
    -h|--help) sed -n '2,27p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "bench-ablation: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
if [ -n "$BUILD" ]; then BIN=$BUILD/bin; else tools/build.sh >/dev/null; BIN=build/bin; fi
[ -x "$BIN/ag-run" ] || { echo "bench-ablation: no ag-run in $BIN" >&2; exit 1; }

# The passes: what paper.pbtxt skips, as STAGE.PASS in the stages' and the
# tables' order (ag-run prints one `skip_passes: PASS` line each).
ALL_PASSES=$("$BIN/ag-run" --print-options --options examples/options/paper.pbtxt |
  awk '/^[a-z_]+ \{$/ { stage = $1 } $1 == "skip_passes:" { print stage "." $2 }')
[ -n "$ALL_PASSES" ] || { echo "bench-ablation: no skip_passes in paper.pbtxt" >&2; exit 1; }
# stage_pass PASS: STAGE.PASS for a pass named with or without its stage.
stage_pass() {
  local name
  for name in $ALL_PASSES; do
    if [ "$name" = "$1" ] || [ "${name#*.}" = "$1" ]; then echo "$name"; return; fi
  done
  echo "bench-ablation: no pass '$1' in paper.pbtxt's skip_passes" >&2
  exit 2
}
if [ "$CHECK" = 1 ]; then
  for pass in $ALL_PASSES; do
    "$BIN/ag-run" --print-options --set "${pass%%.*}.skip_passes=${pass#*.}" >/dev/null
  done
  echo "bench-ablation: $(wc -w <<<"$ALL_PASSES") passes"
  exit 0
fi
PASSES=${PASSES:-$(echo $ALL_PASSES | tr ' ' ',')}
[ "$PASSES" = none ] && PASSES=
# Every name checked before any set runs.
for name in ${PASSES//,/ }; do stage_pass "$name" >/dev/null || exit 2; done

wanted() { [[ ",$SETS," == *",$1,"* ]]; }
rm -rf "$OUT"
mkdir -p "$OUT"

# shellcheck source=tools/bench-sets.sh
source tools/bench-sets.sh

# mean SET RUN [ag-run flags]: the set's mean MCC with those flags; labels
# in $OUT/SET/RUN. The defaults and the passes of cut, merge and match start
# from the set's store of the first four stages, which they do not change.
mean() {
  local set=$1 run=$2 seed=
  shift 2
  case "$run" in
    defaults | cut.* | merge.* | match.*) seed=$(upstream_store "$set" "$BIN") ;;
  esac
  SEED_STORE=$seed score_part "$set" "$OUT/$set/$run" "$BIN" "$@"
}

sets=()
for set in ${SETS//,/ }; do wanted "$set" && sets+=("$set"); done
header="| run |"
rule="|---|"
for set in "${sets[@]}"; do header+=" $set |"; rule+="---|"; set_manifest "$set"; done
echo "Mean MCC (maoris), $(date -u +%Y-%m-%d): the defaults, and each pass's effect on it"
echo "(the mean without the pass minus the defaults'; negative: the pass helps)."
echo
echo "$header"
echo "$rule"
declare -A base
row="| defaults |"
for set in "${sets[@]}"; do
  base[$set]=$(mean "$set" defaults)
  row+=" ${base[$set]} |"
done
echo "$row"
for name in ${PASSES//,/ }; do
  pass=$(stage_pass "$name")
  row="| without $pass |"
  for set in "${sets[@]}"; do
    value=$(mean "$set" "$pass" --set "${pass%%.*}.skip_passes=${pass#*.}")
    row+=" $(awk -v a="$value" -v b="${base[$set]}" 'BEGIN { if (a == "" || b == "") print "-"; else printf "%+.3f", a - b }') |"
  done
  echo "$row"
done
