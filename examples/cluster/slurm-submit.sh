#!/usr/bin/env bash
# Queues N shard tasks (a Slurm job array) and the collection step that waits
# for all of them: the index of the shard stores (slurm-index.sbatch), or with
# --merge their merge into one store file (slurm-merge.sbatch).
#   examples/cluster/slurm-submit.sh [--merge] MAPS_DIR STORES_DIR [N [TASKS]]
# TASKS, a Slurm array list such as 3 or 0,5-6 (default: all of 0..N-1),
# queues only those shards, e.g. again after one was cancelled or ran out of
# time: each resumes from what its store already holds, and the new
# collection step indexes (or merges) every shard store. Job logs go to
# STORES_DIR/logs. The last line printed is "shards <array job id> index
# <job id>" (or "... merge <job id>"). Site options (partition, account, ...)
# go in sbatch's SBATCH_* environment variables.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
step=index
if [ "${1:-}" = --merge ]; then
  step=merge
  shift
fi
if [ $# -lt 2 ] || [ $# -gt 4 ]; then
  echo "usage: slurm-submit.sh [--merge] MAPS_DIR STORES_DIR [N [TASKS]]" >&2
  exit 2
fi
maps="$1"
stores="$2"
shards="${3:-8}"
tasks="${4:-0-$((shards - 1))}"
mkdir -p "$stores/logs"
array=$(sbatch --parsable --array="$tasks" --output="$stores/logs/shard-%a-job%A.out" \
  "$here/slurm-shard.sbatch" "$maps" "$stores" "$shards")
array="${array%%;*}"  # --parsable prints "id;cluster" on multi-cluster sites
last=$(sbatch --parsable --dependency="afterok:$array" --output="$stores/logs/$step-job%j.out" \
  "$here/slurm-$step.sbatch" "$stores")
last="${last%%;*}"
echo "shards $array $step $last"
