#!/usr/bin/env bash
# Queues N shard tasks and the merge step that waits for all of them.
#   examples/cluster/slurm-submit.sh MAPS_DIR STORES_DIR [N]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
maps="$1"
stores="$2"
shards="${3:-8}"
array=$(sbatch --parsable --array="0-$((shards - 1))" "$here/slurm-shard.sbatch" "$maps" "$stores")
sbatch --dependency="afterok:$array" "$here/slurm-merge.sbatch" "$stores"
echo "queued shards as job $array and the merge after it"
