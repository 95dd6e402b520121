#include "tools/bench/exploration_truth.h"

#include <CLI/CLI.hpp>
#include <opencv2/imgproc.hpp>

#include "common/error.h"
#include "stages/common/png_file.h"
#include "stages/common/stage_info.h"
#include "tools/eval/label_image.h"
#include "tools/eval/map_evaluation.h"
#include "tools/example_maps/random_floor_plan.h"

namespace areagraph {

void AddExplorationRunOptions(CLI::App& app, ExplorationRun& run, const std::string& name_help) {
  app.add_option("--name", run.name, name_help)->required();
  app.add_option("--map", run.map_path, "map image (the whole building)");
  app.add_option("--gt", run.gt_path, "its ground truth (colour or line style, as ag-eval)");
  app.add_option("--generated", run.generated_m,
                 "instead of --map: a generated office floor this many metres square");
  app.add_option("--seed", run.seed, "seed of the generated floor and of the noise")
      ->capture_default_str();
  app.add_option("--steps", run.steps, "growing maps")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  app.add_option("--noise-steps", run.noise_steps, "noise-only maps after the last step")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000));
}

ExplorationTruth LoadExplorationTruth(const std::string& map_path, const std::string& gt_path,
                                      double generated_m, uint32_t seed) {
  ExplorationTruth truth;
  if (generated_m > 0) {
    floorplan::FloorPlan closed(1, 1);
    const floorplan::FloorPlan plan =
        floorplan::LargeOfficePlan(generated_m, generated_m, seed, &closed);
    truth.cells = floorplan::ClassifyGrey(plan.image());
    cv::connectedComponents(closed.image() == floorplan::kFreeGrey, truth.rooms, 4, CV_32S);
    DropSmallSegments(&truth.rooms, 100);
    return truth;
  }
  truth.cells = floorplan::ClassifyGrey(ToGrey8(ReadImageFile(map_path)));
  GroundTruthStyle style = GroundTruthStyle::kAuto;
  truth.rooms = ReadGroundTruthLabels(gt_path, &style);
  if (truth.rooms.size() != truth.cells.size()) {
    throw InputError("the ground truth is " + std::to_string(truth.rooms.cols) + "x" +
                     std::to_string(truth.rooms.rows) + ", the map " +
                     std::to_string(truth.cells.cols) + "x" + std::to_string(truth.cells.rows));
  }
  return truth;
}

proto::GridMap ExplorationGridMap(const floorplan::ExplorationMap& map, int whole_height) {
  proto::GridMap grid;
  grid.set_format_version(kGridMapFormatVersion);
  proto::MapFrame* frame = grid.mutable_frame();
  frame->set_resolution_m(0.05);
  frame->set_origin_x_m(map.crop.x * 0.05);
  frame->set_origin_y_m((whole_height - map.crop.y - map.crop.height) * 0.05);
  frame->set_width_px(map.cells.cols);
  frame->set_height_px(map.cells.rows);
  grid.set_cells(std::string(reinterpret_cast<const char*>(map.cells.data), map.cells.total()));
  return grid;
}

cv::Mat SeenGroundTruth(const floorplan::ExplorationMap& map, const cv::Mat& rooms) {
  cv::Mat gt = rooms(map.crop).clone();
  gt.setTo(0, map.seen(map.crop) == 0);
  return gt;
}

}  // namespace areagraph
