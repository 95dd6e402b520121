#!/usr/bin/env bash
# Routes through the Area Graph (ag-route's router) against the shortest
# 8-connected path through the map's free cells, on ../shared/data's lab_a
# and lab_e (or the maps given): random pairs of free cells at least 3 m
# apart, how much longer the route is than the grid path (median, max, how
# many over 15 %), and the time of one query after the router's set-up,
# beside a grid A* and Dijkstra on the same map (ag-bench-route); grid paths
# through every free cell, and through cells at least 0.15 m clear.
#   tools/bench-route.sh [--pairs N] [--seed S] [--no-build] [--build-dir DIR] [--work DIR] [MAP...]
set -euo pipefail
cd "$(dirname "$0")/.."
bench_name=bench-route
bench_help_lines="2,9"
source tools/bench-common.sh
command_line="tools/bench-route.sh $*"
pairs=200
seed=1
maps=()
while [ $# -gt 0 ]; do
  case "$1" in
    --pairs) pairs="$2"; shift 2 ;;
    --seed) seed="$2"; shift 2 ;;
    --*) bench_option "$@"; shift "$bench_shift" ;;
    *) maps+=("$1"); shift ;;
  esac
done
if [ ${#maps[@]} -eq 0 ]; then
  maps=(../shared/data/areagraph/input/lab_a.png ../shared/data/areagraph/input/lab_e.png)
fi
bench_prepare ag-run ag-bench-route
say "segmenting ${#maps[@]} maps"
"$bin/ag-run" --store "$work/routes.db" --jobs 1 "${maps[@]}" >&2
echo "Routes against the 8-connected grid path, $(date -u +%Y-%m-%d), $command_line"
echo
echo "| map | grid path through | cells | areas | corners / links | set-up ms | pairs | routed | no route | median excess % | max excess % | over 15 % | route ms (median) | route ms (p90) | grid A* ms (median) | grid Dijkstra ms (median) |"
echo "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
# Every free cell, as asked; then only cells at least 0.15 m from occupied and
# unknown ones, where a body 0.3 m wide fits: the gaps the Topology Graph keeps
# (prune.min_clearance_m), so that a gap narrower than any passage does not count.
for map in "${maps[@]}"; do
  name=$(basename "${map%.*}")
  for clearance in 0 0.15; do
    "$bin/ag-bench-route" --store "$work/routes.db" --map "$name" --pairs "$pairs" --seed "$seed" \
      --clearance-m "$clearance"
  done
done
