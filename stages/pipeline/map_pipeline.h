#pragma once

#include <google/protobuf/message.h>

#include <functional>
#include <string>
#include <vector>

#include "proto/pipeline_options.pb.h"
#include "stages/common/stage.h"
#include "store/artifact_store.h"

namespace areagraph {

// clean, voronoi, prune, cut and merge, in pipeline order: the stages that
// read artifacts (InputStagesOf says which).
const std::vector<StageInfo>& PipelineStages();

// The options message of `stage` (any stage, import included) in `options`.
const google::protobuf::Message& StageOptionsOf(const proto::PipelineOptions& options,
                                                const StageInfo& stage);

// The cache keys that clean..merge get when every stage runs on the import
// artifact `import_key` with `options`, in PipelineStages() order. Lets a
// runner see that a map is fully cached without reading any artifact.
std::vector<std::string> PlanPipelineKeys(const std::string& import_key,
                                          const proto::PipelineOptions& options);

// Hears about each stage as it starts and as it ends (either may be empty).
struct PipelineObserver {
  std::function<void(const StageInfo&)> on_start;
  std::function<void(const StageInfo&, const StageRun&)> on_done;
};

// Runs the steps from `first_stage` to `last_stage` (names; both within
// clean..merge) for one imported map, each through RunCachedStage on the
// current heads of its inputs. Throws what the stages throw, and InputError
// naming the stage to run first when an input is missing.
void RunMapPipeline(ArtifactStore& store, const std::string& map_name,
                    const proto::PipelineOptions& options, bool force,
                    const PipelineObserver& observer, const std::string& first_stage = "clean",
                    const std::string& last_stage = "merge");

// Runs clean..merge; `on_stage` hears about every stage as soon as it is done.
void RunMapPipeline(ArtifactStore& store, const std::string& map_name,
                    const proto::PipelineOptions& options, bool force,
                    const std::function<void(const StageInfo&, const StageRun&)>& on_stage);

}  // namespace areagraph
