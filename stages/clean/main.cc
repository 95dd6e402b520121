// ag-clean: outlier and furniture removal on an imported grid map.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>

#include "stages/clean/clean_stage.h"
#include "stages/common/command_line.h"
#include "stages/common/stage.h"
#include "store/artifact_store.h"

using namespace areagraph;

int main(int argc, char** argv) {
  CLI::App app{
      "Removes outliers (CGAL remove_outliers) and furniture (small alpha-shape pieces) from a "
      "map's head GridMap (run ag-import first) and stores the result as a CleanedMap."};
  StageCommandLine flags;
  AddStageFlags(app, flags);
  return RunCommand("ag-clean", app, argc, argv, [&] {
    const proto::PipelineOptions options = LoadPipelineOptions(flags);
    const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(flags.store_path);
    const StageInputs inputs = HeadInputs(*store, flags.map_name, kCleanStage);
    const StageRun run = RunCachedStage(
        *store, flags.map_name, kCleanStage, options.clean(), inputs,
        [&] {
          return std::make_unique<proto::CleanedMap>(CleanGridMap(
              ReadArtifactAs<proto::GridMap>(*store, flags.map_name, inputs.digests[0]),
              options.clean(), flags.map_name));
        },
        flags.force);
    const auto cleaned = ReadHeadArtifact<proto::CleanedMap>(*store, flags.map_name, kCleanStage);
    std::printf(
        "ag-clean: map '%s': %d outlier cells, %d furniture cells in %d pieces removed, %.0f ms, "
        "key %.12s (%s)\n",
        flags.map_name.c_str(), cleaned.removed_outlier_cells_size(),
        cleaned.removed_furniture_cells_size(), cleaned.furniture_shapes_size(), run.elapsed_ms,
        run.cache_key.c_str(), run.cache_hit ? "cached" : "computed");
    return 0;
  });
}
