#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>

#include "proto/artifacts.pb.h"
#include "tools/example_maps/exploration.h"

namespace CLI {
class App;
}

namespace areagraph {

// What an exploration benchmark replays: the map (real, or generated), its
// name and how many growing and noise-only updates. ag-bench-live and
// ag-bench-match take the same options for it.
struct ExplorationRun {
  std::string name;
  std::string map_path;
  std::string gt_path;
  double generated_m = 0;
  uint32_t seed = 1;
  int steps = 20;
  int noise_steps = 3;
};

// Declares --name (with `name_help`), --map, --gt, --generated, --seed,
// --steps and --noise-steps on `app`, filling `run`.
void AddExplorationRunOptions(CLI::App& app, ExplorationRun& run, const std::string& name_help);

// The whole map an exploration runs on: its cells (floorplan cell classes)
// and its ground-truth rooms (CV_32S, 0 none).
struct ExplorationTruth {
  cv::Mat cells;
  cv::Mat rooms;
};

// A real map and its ground truth (colour or line style, as ag-eval reads
// it), or with `generated_m` > 0 a generated office floor that many metres
// square (seed `seed`) whose rooms are the truth. Throws InputError when the
// sizes differ.
ExplorationTruth LoadExplorationTruth(const std::string& map_path, const std::string& gt_path,
                                      double generated_m, uint32_t seed);

// A cropped exploration map as the GridMap a SLAM node would send: the whole
// map's bottom-left corner is the world origin.
proto::GridMap ExplorationGridMap(const floorplan::ExplorationMap& map, int whole_height);

// The ground-truth rooms cropped to the map's grid, 0 where nothing was seen
// yet (CV_32S): what a graph of that map is scored against.
cv::Mat SeenGroundTruth(const floorplan::ExplorationMap& map, const cv::Mat& rooms);

}  // namespace areagraph
