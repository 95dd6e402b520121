// ag-bench-steps: median milliseconds of the steps inside ag-import, ag-clean
// and ag-voronoi per map, to see where a stage's time goes.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>
#include <vector>

#include "stages/clean/clean_parameters.h"
#include "stages/clean/clean_stage.h"
#include "stages/clean/furniture_removal.h"
#include "stages/clean/outlier_removal.h"
#include "stages/common/command_line.h"
#include "stages/geometry/obstacle_sites.h"
#include "stages/import/import_stage.h"
#include "stages/voronoi/voronoi_builder.h"
#include "stages/voronoi/voronoi_stage.h"
#include "tools/bench/median_timer.h"

using namespace areagraph;

namespace {

// The steps, in the order they run and are printed.
enum Step {
  kImport,
  kOutliers,
  kFurniture,
  kClean,
  kSites,
  kDiagram,
  kVoronoi,
  kSerialize,
  kStepCount
};
const char* const kStepNames[kStepCount] = {kImportStage.name,  "outliers", "furniture",
                                            kCleanStage.name,   "sites",    "diagram",
                                            kVoronoiStage.name, "serialize"};

std::vector<double> TimeSteps(const std::string& path, const proto::PipelineOptions& options,
                              int repeat) {
  const std::string name = DefaultMapName(path);
  std::vector<std::vector<double>> samples(kStepCount);
  for (int run = 0; run < repeat; ++run) {
    proto::GridMap grid;
    samples[kImport].push_back(
        ElapsedMs([&] { grid = ImportGridMap(ReadImportSource(path), options.import()); }));
    const int width = grid.frame().width_px();
    const int height = grid.frame().height_px();
    const CleanParameters parameters = CleanParametersFor(options.clean(), grid.frame());

    // The two halves of the clean stage, on a copy of the cells.
    std::string cells = grid.cells();
    samples[kOutliers].push_back(ElapsedMs([&] {
      RemoveOutlierCells(cells, width, height, parameters.outlier_neighbors,
                         parameters.outlier_percent);
    }));
    samples[kFurniture].push_back(ElapsedMs([&] {
      RemoveFurniture(cells, width, height, parameters.alpha_radius_px,
                      parameters.furniture_max_perimeter_px,
                      parameters.keep_wall_pieces ? &parameters.wall_pieces : nullptr);
    }));
    proto::CleanedMap cleaned;
    samples[kClean].push_back(ElapsedMs([&] { cleaned = CleanGridMap(grid, options.clean()); }));

    std::vector<Eigen::Vector2d> sites;
    samples[kSites].push_back(
        ElapsedMs([&] { sites = ObstacleSites(cleaned.cells(), width, height); }));
    samples[kDiagram].push_back(ElapsedMs([&] { BuildVoronoiDiagram(sites); }));
    proto::VoronoiDiagram diagram;
    samples[kVoronoi].push_back(
        ElapsedMs([&] { diagram = ComputeVoronoiStage(cleaned, options.voronoi()); }));

    // What the store adds on top of the computing: the artifacts' bytes.
    samples[kSerialize].push_back(ElapsedMs([&] {
      grid.SerializeAsString();
      cleaned.SerializeAsString();
      diagram.SerializeAsString();
    }));
  }
  std::vector<double> medians;
  for (const std::vector<double>& step : samples) medians.push_back(Median(step));
  return medians;
}

void PrintRow(const std::string& name, const std::vector<double>& values) {
  std::printf("%-44s", name.c_str());
  for (const double value : values) std::printf(" %9.2f", value);
  std::printf("\n");
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Times the steps inside ag-import, ag-clean and ag-voronoi per map, in one process and "
      "without a store: import (read + decode), outliers and furniture (the halves of clean), "
      "clean (the whole stage), sites and diagram (the halves of voronoi), voronoi, and "
      "serialize (the three artifacts' bytes). Prints the median milliseconds of --repeat runs. "
      "A benchmark: it checks nothing."};
  std::vector<std::string> paths;
  int repeat = 5;
  StageCommandLine flags;
  app.add_option("MAP", paths, "map images or map_server YAMLs")->required();
  app.add_option("--repeat", repeat, "runs per map; the median is printed")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  app.add_option("--options", flags.options_file, "PipelineOptions in protobuf text format");
  app.add_option("--set", flags.overrides, "override one option (repeatable)");
  return RunCommand("ag-bench-steps", app, argc, argv, [&] {
    const proto::PipelineOptions options = LoadPipelineOptions(flags);
    std::printf("%-44s", "map (median ms)");
    for (const char* step : kStepNames) std::printf(" %9s", step);
    std::printf("\n");
    std::vector<double> total(kStepCount, 0.0);
    for (const std::string& path : paths) {
      const std::vector<double> medians = TimeSteps(path, options, repeat);
      for (int step = 0; step < kStepCount; ++step) total[step] += medians[step];
      PrintRow(DefaultMapName(path), medians);
    }
    PrintRow("total", total);
    return 0;
  });
}
