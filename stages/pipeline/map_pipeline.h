#pragma once

#include <functional>
#include <string>
#include <vector>

#include "proto/pipeline_options.pb.h"
#include "stages/pipeline/stage.h"
#include "store/artifact_store.h"

namespace areagraph {

// Where a stage that reads its previous version stands when it runs on
// `input_keys` (PreviousVersionOf on a store).
using PreviousVersionLookup = std::function<VersionLink(
    const StageDefinition& stage, const std::vector<std::string>& input_keys)>;

// The cache keys that the stages after import get when every one runs on the
// import artifact `import_key` with `options`, in PipelineStages() order.
// Lets a runner see that a map is fully cached without reading any artifact.
// A stage that reads its previous version takes its place in the history
// from `previous`; without one it is planned as the map's first version.
std::vector<std::string> PlanPipelineKeys(const std::string& import_key,
                                          const proto::PipelineOptions& options,
                                          const PreviousVersionLookup& previous = nullptr);

// Hears about each stage as it starts and as it ends, and is the hook that
// computes call between their big steps (InputRelease::between_steps); any
// may be empty.
struct PipelineObserver {
  std::function<void(const StageInfo&)> on_start;
  std::function<void(const StageInfo&, const StageRun&)> on_done;
  std::function<void()> between_steps;
};

// Runs the stages from `first` to `last` (both after import, `first` not
// after `last`) for one imported map, each through RunStageOnHeads. Throws
// what the stages throw (MapStepError), and InputError naming the stage to
// run first when an input is missing. Each computed artifact goes to the
// next stages in memory (through `memo`, which may already hold the import's
// artifact, or a memo of its own when null) and is dropped once no later
// stage reads it; `last`'s stays in `memo` when it was computed. Returns once
// every artifact is in the store (ArtifactStore::FinishWrites).
void RunMapPipeline(ArtifactStore& store, const std::string& map_name,
                    const proto::PipelineOptions& options, bool force,
                    const PipelineObserver& observer, const StageInfo& first, const StageInfo& last,
                    ArtifactMemo* memo = nullptr);

// Runs every stage after import; `on_stage` hears about each as soon as it is
// done.
void RunMapPipeline(ArtifactStore& store, const std::string& map_name,
                    const proto::PipelineOptions& options, bool force,
                    const std::function<void(const StageInfo&, const StageRun&)>& on_stage);

}  // namespace areagraph
