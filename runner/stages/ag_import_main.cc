// ag-import: decodes a map image (and its map_server YAML) into the store's
// GridMap for the map. The input is decoded and checked before the store is
// opened, so bad input never creates or changes a store.
#include <CLI/CLI.hpp>
#include <cmath>
#include <iostream>
#include <sstream>

#include "common/error.h"
#include "common/map_name.h"
#include "common/text.h"
#include "stages/common/command_line.h"
#include "stages/common/grid_cells.h"
#include "stages/common/pipeline_options_check.h"
#include "stages/import/grid_map_decoder.h"
#include "stages/import/import_stage.h"
#include "stages/pipeline/stage.h"
#include "store/artifact_store.h"

namespace areagraph {
namespace {

int Import(StageCommandLine& flags, const std::string& image, const CLI::Option& resolution_flag,
           double resolution_m) {
  proto::PipelineOptions options = LoadPipelineOptions(flags);
  if (resolution_flag.count() > 0) {
    CheckResolution(resolution_m, "--resolution", /*is_option=*/true);
    options.mutable_import()->set_resolution_m(resolution_m);
  }
  CheckPipelineOptions(options);
  const ImportSource source = ReadImportSource(image);
  if (resolution_flag.count() > 0 && source.yaml && source.yaml->resolution_m != resolution_m) {
    std::ostringstream message;
    message << "--resolution " << resolution_m << " contradicts resolution "
            << source.yaml->resolution_m << " in '" << *source.yaml_path
            << "'; edit the YAML or drop --resolution";
    throw OptionsError(message.str());
  }
  const std::string map_name = flags.map_name.empty() ? DefaultMapName(image) : flags.map_name;
  if (map_name.empty()) throw InputError("cannot name the map after '" + image + "'; use --name");
  CheckMapName(map_name);

  // Everything that can be wrong with the input fails here, before the store.
  const proto::GridMap grid = ImportGridMap(source, options.import());

  const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(flags.store_path);
  const StageRun run = RunCachedStage(
      *store, map_name, StageOf(kImportStage), options, ImportInputs(source),
      [&grid] { return std::make_unique<proto::GridMap>(grid); }, flags.force);

  std::cout << "imported " << map_name << ": " << run.summary << " (key " << ShortKey(run.cache_key)
            << ", " << (run.cache_hit ? "cached" : "stored") << ")\n";
  if (CountCells(grid.cells()).occupied == 0) {
    std::cerr << "ag-import: warning: map '" << map_name
              << "' has no occupied cells; if its walls are lighter than grey "
              << options.import().occupied_max_grey()
              << ", raise import.occupied_max_grey (--set import.occupied_max_grey=N)\n";
  }
  return 0;
}

}  // namespace
}  // namespace areagraph

int main(int argc, char** argv) {
  using namespace areagraph;
  CLI::App app{
      "Decodes a map image (PNG, PGM, ...; 8 or 16 bit; grey, colour, palette, with or "
      "without alpha) into occupied, free and unknown cells and stores it as the map's "
      "GridMap. A ROS map_server YAML beside the image (same stem, .yaml), or given instead "
      "of the image, sets resolution, origin and thresholds. Without one, grey >= "
      "import.free_min_grey (250) is free, grey <= import.occupied_max_grey (100) is "
      "occupied, and the rest unknown."};
  StageCommandLine flags;
  AddStageFlags(app, flags, /*map_required=*/false);
  app.add_option("--name", flags.map_name, "name of the map (default: the file name's stem)")
      ->excludes(app.get_option("--map"));
  double resolution_m = 0;
  const CLI::Option* resolution_flag =
      app.add_option("--resolution", resolution_m,
                     "metres per pixel; sets import.resolution_m (a YAML's resolution "
                     "must agree)");
  std::string image;
  app.add_option("IMAGE", image, "map image, or map_server YAML")->required();
  return RunCommand("ag-import", app, argc, argv,
                    [&] { return Import(flags, image, *resolution_flag, resolution_m); });
}
