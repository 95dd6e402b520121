#!/usr/bin/env bash
# Runs ag-bench-live against an ag-live with a new store (DIR/live.db) inside a
# private network namespace (unshare -n, multicast routed on its loopback), so
# that no packet reaches the host's network. ag-live's output goes to
# DIR/live.out and DIR/live.err; ag-bench-live's tables go to stdout. Used by
# tools/bench-live.sh and tools/bench-live-mcc.sh.
#
#   tools/bench/live-in-namespace.sh BIN_DIR DIR [ag-live flags] -- [ag-bench-live flags]
set -euo pipefail
if [ $# -lt 2 ]; then
  echo "live-in-namespace: usage: BIN_DIR DIR [ag-live flags] -- [ag-bench-live flags]" >&2
  exit 2
fi
if [ "${AG_LIVE_NAMESPACE:-}" != 1 ]; then
  AG_LIVE_NAMESPACE=1 exec unshare -n "$0" "$@"
fi
ip link set lo up
ip route add 224.0.0.0/4 dev lo
bin=$1
dir=$2
shift 2
live_flags=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
  live_flags+=("$1")
  shift
done
[ $# -gt 0 ] && shift
"$bin/ag-live" --store "$dir/live.db" "${live_flags[@]}" >"$dir/live.out" 2>"$dir/live.err" &
live=$!
trap 'kill $live 2>/dev/null' EXIT
i=0
until grep -q "ag-live: serving" "$dir/live.err" 2>/dev/null; do
  i=$((i + 1))
  if [ $i -gt 300 ]; then
    cat "$dir/live.err" >&2
    exit 1
  fi
  sleep 0.1
done
"$bin/ag-bench-live" --live-log "$dir/live.out" --scratch "$dir" "$@"
