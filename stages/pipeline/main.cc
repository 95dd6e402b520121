// ag-pipeline: clean, voronoi, prune, cut and merge for one imported map.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>

#include "stages/common/command_line.h"
#include "stages/merge/area_graph_builder.h"
#include "stages/pipeline/map_pipeline.h"
#include "stages/prune/topology_graph_builder.h"
#include "store/artifact_store.h"

using namespace areagraph;

int main(int argc, char** argv) {
  CLI::App app{
      "Runs ag-clean, ag-voronoi, ag-prune, ag-cut and ag-merge in one go for a map that "
      "ag-import has stored, reusing every cached result; prints one line per stage."};
  StageCommandLine flags;
  AddStageFlags(app, flags);
  return RunCommand("ag-pipeline", app, argc, argv, [&] {
    const proto::PipelineOptions options = LoadPipelineOptions(flags);
    // Bad options fail before any work.
    CheckPruneOptions(options.prune());
    CheckMergeOptions(options.merge());
    const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(flags.store_path);
    RunMapPipeline(*store, flags.map_name, options, flags.force,
                   [&](const StageInfo& stage, const StageRun& run) {
                     std::printf("ag-pipeline: map '%s': %-7s %-8s %6.0f ms  key %.12s\n",
                                 flags.map_name.c_str(), stage.name,
                                 run.cache_hit ? "cached" : "computed", run.elapsed_ms,
                                 run.cache_key.c_str());
                     std::fflush(stdout);
                   });
    const auto graph = ReadHeadArtifact<proto::AreaGraph>(*store, flags.map_name, kMergeStage);
    std::printf("ag-pipeline: map '%s': %d areas, %d passages, %d components, %d parts dropped\n",
                flags.map_name.c_str(), graph.areas_size(), graph.passages_size(),
                graph.components(), graph.dropped_parts());
    return 0;
  });
}
