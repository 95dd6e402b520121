// ag-voronoi: the Voronoi diagram of a cleaned map's obstacle cells.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>

#include "stages/common/command_line.h"
#include "stages/common/stage.h"
#include "stages/voronoi/voronoi_stage.h"
#include "store/artifact_store.h"

using namespace areagraph;

int main(int argc, char** argv) {
  CLI::App app{
      "Computes the Voronoi diagram of the obstacle cells next to free space of a map's head "
      "CleanedMap (run ag-clean first) and stores it as a VoronoiDiagram."};
  StageCommandLine flags;
  AddStageFlags(app, flags);
  return RunCommand("ag-voronoi", app, argc, argv, [&] {
    const proto::PipelineOptions options = LoadPipelineOptions(flags);
    const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(flags.store_path);
    const StageInputs inputs = HeadInputs(*store, flags.map_name, kVoronoiStage);
    const StageRun run = RunCachedStage(
        *store, flags.map_name, kVoronoiStage, options.voronoi(), inputs,
        [&] {
          return std::make_unique<proto::VoronoiDiagram>(ComputeVoronoiStage(
              ReadArtifactAs<proto::CleanedMap>(*store, flags.map_name, inputs.digests[0]),
              options.voronoi(), flags.map_name));
        },
        flags.force);
    const auto diagram =
        ReadHeadArtifact<proto::VoronoiDiagram>(*store, flags.map_name, kVoronoiStage);
    std::printf("ag-voronoi: map '%s': %d sites, %d vertices, %d edges, %.0f ms, key %.12s (%s)\n",
                flags.map_name.c_str(), diagram.sites_size(), diagram.vertices_size(),
                diagram.edges_size(), run.elapsed_ms, run.cache_key.c_str(),
                run.cache_hit ? "cached" : "computed");
    return 0;
  });
}
