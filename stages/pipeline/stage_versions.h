#pragma once

#include <string>
#include <vector>

#include "proto/pipeline_options.pb.h"
#include "stages/common/stage_info.h"
#include "stages/pipeline/stage_table.h"
#include "store/artifact_store.h"

namespace areagraph {

// Where a run of `stage` (one that reads its previous version) on the inputs
// `input_keys` stands in the map's history. Its predecessor is the stage's
// current head, except when that head is already what this run would make
// (the same options, inputs and predecessor): then the head's own
// predecessor, so that the run's key is the head's and the run a cache hit.
// The first version (no head yet) has no predecessor and number 1. Reads keys
// and the history only, never a payload.
VersionLink PreviousVersionOf(ArtifactStore& store, const std::string& map_name,
                              const StageDefinition& stage, const proto::PipelineOptions& options,
                              const std::vector<std::string>& input_keys);

// The keys that enter a stage's cache key: its inputs', then its
// predecessor's when it has one.
std::vector<std::string> CacheKeyInputs(const std::vector<std::string>& input_keys,
                                        const std::optional<VersionLink>& version);

// The key of a map's newest Area Graph: the final stage's head (match: the
// graph with stable ids), unless the head of its first input (merge) is
// newer than what it was made from, as after ag-merge alone; then that
// input's head. nullopt when the map has neither; throws StoreError when the
// final stage's head cannot be found by its key (a damaged row or index).
std::optional<std::string> NewestGraphKey(ArtifactStore& store, const std::string& map_name);

}  // namespace areagraph
