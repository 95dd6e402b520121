#include "tests/stages/match/plan_runs.h"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "stages/import/import_stage.h"
#include "stages/pipeline/stage.h"

namespace areagraph::testing {

MapOutcome RunPlan(ArtifactStore& store, const std::string& map_name, const cv::Mat& grey,
                   const proto::PipelineOptions& options) {
  ImportSource source;
  source.given_path = source.image_path = map_name + ".png";
  std::vector<uchar> png;
  cv::imencode(".png", grey, png);
  source.image_bytes.assign(png.begin(), png.end());
  MapImport map_import;
  map_import.read_inputs = [&] { return ImportInputs(source); };
  map_import.decode = [&] {
    return std::make_unique<proto::GridMap>(ImportGridMap(source, options.import()));
  };
  FailureLog failures(store);
  const MapOutcome outcome = RunOneMap(store, failures, map_name, source.image_path, map_import,
                                       options, MapRunSettings(), PipelineObserver(), nullptr);
  EXPECT_TRUE(outcome.ok) << map_name << ": " << outcome.failed_step << ": " << outcome.error;
  return outcome;
}

proto::AreaGraph MatchedGraph(ArtifactStore& store, const std::string& map_name, std::string* key) {
  return ReadHeadArtifact<proto::AreaGraph>(store, map_name, kMatchStage, key);
}

int StableIdAt(const proto::AreaGraph& graph, double x_m, double y_m) {
  const double resolution = graph.frame().resolution_m();
  const std::vector<cv::Point2d> probe = {{x_m / resolution, y_m / resolution}};
  for (const proto::Area& area : graph.areas()) {
    std::vector<cv::Point2f> ring;
    for (const proto::Point2& point : area.polygon_px().outer().points()) {
      ring.emplace_back(static_cast<float>(point.x()), static_cast<float>(point.y()));
    }
    if (ring.size() >= 3 && cv::pointPolygonTest(ring, cv::Point2f(probe[0]), false) > 0) {
      return area.stable_id();
    }
  }
  return -1;
}

proto::PipelineOptions FixedWidthOptions(double room_width_m) {
  proto::PipelineOptions options;
  options.mutable_cut()->set_room_width_m(room_width_m);
  return options;
}

}  // namespace areagraph::testing
