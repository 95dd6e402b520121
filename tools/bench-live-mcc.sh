#!/usr/bin/env bash
# Does match holding the segmentation still (folding small pieces back,
# match.fold_fragments_below_m2, and cutting joins apart,
# match.split_joins_below_m2) make the live graph worse than a fresh
# segmentation? Runs the simulated explorations of tools/bench-live.sh
# (ag-bench-live --no-cold --dump, same maps, seeds and noise) twice through
# an ag-live with a new store: with the default options and with both set to
# 0 (merge's areas as they are); then runs every grid sent cold with ag-run, each as a map of its
# own in one new store (no predecessor to match, no cache key shared). Checks
# that both explorations sent the same grids. Every graph is scored by ag-eval
# (MAORIS' MCC variant, as tools/bench-quality.sh uses it) against the ground
# truth cropped to the grid and to what was seen so far. Prints Markdown
# tables on stdout (progress on stderr); a benchmark: it checks nothing.
# Needs 'unshare -n' (root).
#
# Usage: tools/bench-live-mcc.sh [--no-build] [--build-dir DIR] [--data DIR]
#                                [--only NAME] [--work DIR (kept)]
set -euo pipefail
cd "$(dirname "$0")/.."
bench_name=bench-live-mcc
bench_help_lines=2,17
source tools/bench-common.sh
data=../shared/data
only=""
while [ $# -gt 0 ]; do
  case "$1" in
    --data) data="$2"; shift 2 ;;
    --only) only="$2"; shift 2 ;;
    *) bench_option "$@"; shift "$bench_shift" ;;
  esac
done
bench_prepare ag-live ag-bench-live ag-run ag-export ag-eval
if ! unshare -n true 2>/dev/null; then
  say "needs 'unshare -n' (a private network namespace); run as root"
  exit 1
fi

maps=(
  "freiburg_building79|--map $data/bormann/freiburg_building79.png --gt $data/areagraph/GT/freiburg_building79.png"
  "lab_e|--map $data/areagraph/input/lab_e.png --gt $data/areagraph/GT/lab_e.png"
)

# live NAME DIR [ag-live flags] -- [ag-bench-live flags]: one exploration
# through an ag-live with a new store, dumped into DIR.
live() {
  local name=$1 dir=$2
  shift 2
  mkdir -p "$dir"
  tools/bench/live-in-namespace.sh "$bin" "$dir" "$@" --name "$name" --no-cold --dump "$dir" \
    >"$dir/bench.md"
  rm -f "$dir"/live.db*
}

# mcc DIR GT -> "map<TAB>mcc" lines (as tools/bench-quality.sh scores)
mcc() {
  { "$bin/ag-eval" --dataset --results "$1" --gt "$2" --gt-style labels --mcc-variant maoris \
      2>/dev/null || true; } |
    awk -F'|' 'NR > 2 { gsub(/[ *]/, "", $2); gsub(/[ *]/, "", $3); print $2 "\t" $3 }'
}

echo "### MCC of the live graph against a cold run, $(date -u +%Y-%m-%d), $(nproc) cores (shared machine)"
echo
for entry in "${maps[@]}"; do
  name=${entry%%|*}
  args=${entry#*|}
  [ -n "$only" ] && [ "$only" != "$name" ] && continue
  say "$name, folding"
  # shellcheck disable=SC2086
  live "$name" "$work/$name/fold" -- $args
  say "$name, neither folding nor join splitting"
  # shellcheck disable=SC2086
  live "$name" "$work/$name/nofold" --set match.fold_fragments_below_m2=0 \
    --set match.split_joins_below_m2=0 -- $args
  say "$name, cold runs"
  mkdir -p "$work/$name/cold"
  "$bin/ag-run" --store "$work/$name/cold.db" "$work/$name/fold/grid" >"$work/$name/cold.log" 2>&1 ||
    say "some cold runs failed (see $work/$name/cold.log)"
  for grid in "$work/$name/fold/grid"/*.png; do
    step=$(basename "$grid" .png)
    "$bin/ag-export" --store "$work/$name/cold.db" --map "$step" --format labels \
      --out "$work/$name/cold/$step.png" >/dev/null 2>&1 ||
      say "no cold result for $step"
  done
  rm -f "$work/$name"/cold.db*
  gt="$work/$name/fold/gt"
  if ! cmp -s <(cd "$work/$name/fold/grid" && md5sum ./*.png) \
    <(cd "$work/$name/nofold/grid" && md5sum ./*.png); then
    say "$name: the two explorations sent different grids"
    exit 1
  fi
  echo "#### $name"
  echo
  echo "| update | MCC live, defaults (a) | live, no folding or join splitting (b) | cold (c) | (a) - (c) | (b) - (c) |"
  echo "|---|---|---|---|---|---|"
  join -t $'\t' <(mcc "$work/$name/fold/live" "$gt" | sort) \
    <(mcc "$work/$name/nofold/live" "$gt" | sort) |
    join -t $'\t' - <(mcc "$work/$name/cold" "$gt" | sort) |
    grep -v -e '^mean' -e '^median' |
    awk -F'\t' '{ step = $1; sub(/.*_/, "", step)
      printf "| %d | %.3f | %.3f | %.3f | %+.3f | %+.3f |\n", step, $2, $3, $4, $2 - $4, $3 - $4 }' | tee "$work/$name/rows.md"
  echo
  awk -F'|' -v name="$name" '
    { a[NR] = $6 + 0; b[NR] = $7 + 0; last_a = $3 + 0; last_b = $4 + 0; last_c = $5 + 0 }
    function median(v, n,   i, j, t) {
      for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (v[j] < v[i]) { t = v[i]; v[i] = v[j]; v[j] = t }
      return n % 2 ? v[(n + 1) / 2] : (v[n / 2] + v[n / 2 + 1]) / 2
    }
    END {
      printf "%s: last update (a) %.3f, (b) %.3f, (c) %.3f; median over the %d updates of (a) - (c) %+.3f, of (b) - (c) %+.3f.\n\n",
        name, last_a, last_b, last_c, NR, median(a, NR), median(b, NR)
    }' "$work/$name/rows.md"
done
