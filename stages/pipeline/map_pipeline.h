#pragma once

#include <functional>
#include <string>

#include "proto/pipeline_options.pb.h"
#include "stages/common/stage.h"
#include "store/artifact_store.h"

namespace areagraph {

// Runs ag-clean, ag-voronoi, ag-prune, ag-cut and ag-merge for one imported
// map, each through RunCachedStage with the same inputs as the stage
// executables (so their caches are shared). `on_stage` hears about every
// stage as soon as it is done. Throws what the stages throw.
void RunMapPipeline(ArtifactStore& store, const std::string& map_name,
                    const proto::PipelineOptions& options, bool force,
                    const std::function<void(const StageInfo&, const StageRun&)>& on_stage);

}  // namespace areagraph
