// ag-merge: the Area Graph from a map's cut graph.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>

#include "stages/common/command_line.h"
#include "stages/common/stage.h"
#include "stages/merge/area_graph_builder.h"
#include "store/artifact_store.h"

using namespace areagraph;

int main(int argc, char** argv) {
  CLI::App app{
      "Merges the edges of a map's head CutGraph (run ag-cut first) into areas: one per room, "
      "one per room-less edge. Splits the free space among them, traces their polygons and "
      "finds the passages between them. Stores the AreaGraph."};
  StageCommandLine flags;
  AddStageFlags(app, flags);
  return RunCommand("ag-merge", app, argc, argv, [&] {
    const proto::PipelineOptions options = LoadPipelineOptions(flags);
    CheckMergeOptions(options.merge());
    const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(flags.store_path);
    const StageInputs inputs = HeadInputs(*store, flags.map_name, kMergeStage);
    const StageRun run = RunCachedStage(
        *store, flags.map_name, kMergeStage, options.merge(), inputs,
        [&] {
          return std::make_unique<proto::AreaGraph>(BuildAreaGraph(
              ReadArtifactAs<proto::CutGraph>(*store, flags.map_name, inputs.digests[0]),
              ReadArtifactAs<proto::CleanedMap>(*store, flags.map_name, inputs.digests[1]),
              options.merge(), flags.map_name));
        },
        flags.force);
    const auto area_graph = ReadHeadArtifact<proto::AreaGraph>(*store, flags.map_name, kMergeStage);
    std::printf("ag-merge: map '%s': %d areas, %d passages, %.0f ms, key %.12s (%s)\n",
                flags.map_name.c_str(), area_graph.areas_size(), area_graph.passages_size(),
                run.elapsed_ms, run.cache_key.c_str(), run.cache_hit ? "cached" : "computed");
    return 0;
  });
}
