// ag-bench-floor: the least work any Voronoi-based pipeline does per map -
// read and decode the image as ag-import does, find the obstacle cells next to
// free space and Delaunay-triangulate them - timed as medians of repeats.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>
#include <vector>

#include "stages/common/command_line.h"
#include "stages/geometry/obstacle_sites.h"
#include "stages/import/import_stage.h"
#include "tools/bench/floor_triangulation.h"
#include "tools/bench/median_timer.h"

using namespace areagraph;

namespace {

// Median milliseconds of the parts of one map's floor, and of the whole.
struct FloorTimes {
  std::string size;
  size_t sites = 0;
  double decode_ms = 0;
  double sites_ms = 0;
  double delaunay_ms = 0;
  double floor_ms = 0;
};

FloorTimes TimeFloor(const std::string& path, int repeat) {
  FloorTimes times;
  std::vector<double> decode, sites, delaunay, whole;
  for (int run = 0; run < repeat; ++run) {
    proto::GridMap grid;
    std::vector<Eigen::Vector2d> centres;
    size_t faces = 0;
    decode.push_back(
        ElapsedMs([&] { grid = ImportGridMap(ReadImportSource(path), proto::ImportOptions()); }));
    const int width = grid.frame().width_px();
    const int height = grid.frame().height_px();
    sites.push_back(ElapsedMs([&] { centres = ObstacleSites(grid.cells(), width, height); }));
    delaunay.push_back(ElapsedMs([&] { faces = TriangulateSites(centres); }));
    whole.push_back(decode.back() + sites.back() + delaunay.back());
    times.size = std::to_string(width) + "x" + std::to_string(height);
    times.sites = centres.size();
    if (faces == 0 && centres.size() > 2) {
      std::fprintf(stderr, "%s: sites on one line\n", path.c_str());
    }
  }
  times.decode_ms = Median(decode);
  times.sites_ms = Median(sites);
  times.delaunay_ms = Median(delaunay);
  times.floor_ms = Median(whole);
  return times;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Times the speed floor of a Voronoi-based pipeline per map: reading and decoding the "
      "image exactly as ag-import does, finding the obstacle cells next to free space "
      "(ObstacleSites) and inserting them into a CGAL Delaunay triangulation. Prints the "
      "median milliseconds of --repeat runs per map and their sum. A benchmark: it checks "
      "nothing."};
  std::vector<std::string> paths;
  int repeat = 5;
  app.add_option("MAP", paths, "map images or map_server YAMLs")->required();
  app.add_option("--repeat", repeat, "runs per map; the median is printed")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  return RunCommand("ag-bench-floor", app, argc, argv, [&] {
    std::printf("%-44s %10s %7s %10s %8s %11s %9s\n", "map", "size", "sites", "decode_ms",
                "sites_ms", "delaunay_ms", "floor_ms");
    FloorTimes total;
    for (const std::string& path : paths) {
      const FloorTimes times = TimeFloor(path, repeat);
      std::printf("%-44s %10s %7zu %10.2f %8.2f %11.2f %9.2f\n", DefaultMapName(path).c_str(),
                  times.size.c_str(), times.sites, times.decode_ms, times.sites_ms,
                  times.delaunay_ms, times.floor_ms);
      std::fflush(stdout);
      total.sites += times.sites;
      total.decode_ms += times.decode_ms;
      total.sites_ms += times.sites_ms;
      total.delaunay_ms += times.delaunay_ms;
      total.floor_ms += times.floor_ms;
    }
    std::printf("%-44s %10s %7zu %10.2f %8.2f %11.2f %9.2f\n", "total", "", total.sites,
                total.decode_ms, total.sites_ms, total.delaunay_ms, total.floor_ms);
    return 0;
  });
}
