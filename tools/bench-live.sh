#!/usr/bin/env bash
# Times ag-live on a simulated exploration and measures how stable the area
# ids stay: tools/bench/bench_live_main.cc (ag-bench-live) explores a map with
# a simulated robot (360-degree 8 m range sensor, frontier by frontier), cuts
# its path into 20 growing maps with fresh scan noise each, then sends 3
# noise-only maps, all over LCM to an ag-live with a new store. Everything
# runs inside a private network namespace (unshare -n) with multicast routed
# on its loopback, so no packet reaches the host's network. Prints Markdown
# tables on stdout (progress on stderr); a benchmark: it checks nothing.
#
# Maps: freiburg_building79 (../shared/data/bormann, ground truth from
# ../shared/data/areagraph/GT), lab_e (../shared/data/areagraph/input and GT),
# and a generated 100 m x 100 m office floor (2000 x 2000 px; its rooms are
# the ground truth).
#
# Usage: tools/bench-live.sh [--no-build] [--build-dir DIR] [--data DIR]
#                            [--only NAME] [--no-cold] [--generated-m M]
set -euo pipefail
cd "$(dirname "$0")/.."

build=1
build_dir=build
data=../shared/data
only=""
cold_flag=""
generated_m=100
while [ $# -gt 0 ]; do
  case "$1" in
    --no-build) build=0; shift ;;
    --build-dir) build_dir="$2"; shift 2 ;;
    --data) data="$2"; shift 2 ;;
    --only) only="$2"; shift 2 ;;
    --no-cold) cold_flag="--no-cold"; shift ;;
    --generated-m) generated_m="$2"; shift 2 ;;
    -h|--help) sed -n '2,17p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "bench-live: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done

if [ "$build" = 1 ]; then
  if [ "$build_dir" != build ]; then
    echo "bench-live: --build-dir needs --no-build (tools/build.sh builds into build/)" >&2
    exit 2
  fi
  tools/build.sh >&2
fi
bin="$(cd "$build_dir/bin" && pwd)"
for tool in ag-live ag-bench-live; do
  if [ ! -x "$bin/$tool" ]; then
    echo "bench-live: $bin/$tool is missing; build it first" >&2
    exit 1
  fi
done
if ! unshare -n true 2>/dev/null; then
  echo "bench-live: needs 'unshare -n' (a private network namespace); run as root" >&2
  exit 1
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# name, then the ag-bench-live arguments that give its map and ground truth.
maps=(
  "freiburg_building79|--map $data/bormann/freiburg_building79.png --gt $data/areagraph/GT/freiburg_building79.png"
  "lab_e|--map $data/areagraph/input/lab_e.png --gt $data/areagraph/GT/lab_e.png"
  "generated_floor|--generated $generated_m"
)

echo "### ag-live on a simulated exploration, $(date -u +%Y-%m-%d), $(nproc) cores (shared machine)"
echo
for entry in "${maps[@]}"; do
  name=${entry%%|*}
  args=${entry#*|}
  [ -n "$only" ] && [ "$only" != "$name" ] && continue
  echo "#### $name"
  echo
  # One namespace per map: ag-live in the background, the driver in front.
  # shellcheck disable=SC2086
  tools/bench/live-in-namespace.sh "$bin" "$work" -- --name "$name" $args $cold_flag
  rm -f "$work"/live.db*
done
