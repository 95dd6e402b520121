// MapThumbnailPng draws the published graph (the match artifact, stable ids)
// and falls back to merge's only when a run has no match artifact.
#include "tools/report/map_thumbnail.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>  // the IMREAD_ flags

#include "proto/artifacts.pb.h"
#include "stages/common/image_codecs.h"
#include "stages/pipeline/stage.h"

namespace areagraph {
namespace {

constexpr int kWidth = 40;
constexpr int kHeight = 20;

ArtifactRecord Record(const StageInfo& stage, const google::protobuf::Message& message) {
  ArtifactRecord record;
  record.stage = stage.name;
  record.payload = message.SerializeAsString();
  return record;
}

ArtifactRecord FreeGrid() {
  proto::GridMap grid;
  grid.mutable_frame()->set_resolution_m(0.05);
  grid.mutable_frame()->set_width_px(kWidth);
  grid.mutable_frame()->set_height_px(kHeight);
  grid.set_cells(std::string(kWidth * kHeight, static_cast<char>(proto::CELL_FREE)));
  return Record(kImportStage, grid);
}

// A graph of one area covering pixel columns [x0, x1) of the whole height.
proto::AreaGraph OneArea(int x0, int x1) {
  proto::AreaGraph graph;
  proto::Area* area = graph.add_areas();
  area->set_id(0);
  area->set_stable_id(0);
  area->set_kind(proto::AREA_ROOM);
  for (const auto& [x, y] : {std::pair{x0, 0}, {x1, 0}, {x1, kHeight}, {x0, kHeight}}) {
    proto::Point2* point = area->mutable_polygon_px()->mutable_outer()->add_points();
    point->set_x(x);
    point->set_y(y);
  }
  return graph;
}

cv::Mat Thumbnail(const std::vector<ArtifactRecord>& run) {
  const std::string png = MapThumbnailPng(run, 100);
  EXPECT_FALSE(png.empty());
  return DecodeImage(png, cv::IMREAD_COLOR);
}

bool SamePixels(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0;
}

TEST(MapThumbnailTest, DrawsTheMatchArtifactOverMerges) {
  const ArtifactRecord merge = Record(kMergeStage, OneArea(0, kWidth / 2));
  const ArtifactRecord match = Record(kMatchStage, OneArea(kWidth / 2, kWidth));
  const cv::Mat both = Thumbnail({FreeGrid(), merge, match});
  const cv::Mat match_only = Thumbnail({FreeGrid(), match});
  const cv::Mat merge_only = Thumbnail({FreeGrid(), merge});
  ASSERT_FALSE(both.empty());
  EXPECT_TRUE(SamePixels(both, match_only));
  EXPECT_FALSE(SamePixels(both, merge_only));
  // A run that stopped before match still shows merge's areas.
  EXPECT_FALSE(SamePixels(merge_only, Thumbnail({FreeGrid()})));
}

// The thumbnail keys areas by stable id, as the viewer and the exports do:
// an area drawn with stable id 7 looks as an area whose only id is 7.
TEST(MapThumbnailTest, ColoursAndLabelsAreasByStableId) {
  proto::AreaGraph matched = OneArea(0, kWidth);
  matched.mutable_version()->set_number(2);
  matched.mutable_areas(0)->set_stable_id(7);
  proto::AreaGraph indexed = OneArea(0, kWidth);
  indexed.mutable_areas(0)->set_id(7);
  proto::AreaGraph renumbered = matched;
  renumbered.mutable_areas(0)->set_stable_id(3);
  const cv::Mat seven = Thumbnail({FreeGrid(), Record(kMatchStage, matched)});
  EXPECT_TRUE(SamePixels(seven, Thumbnail({FreeGrid(), Record(kMatchStage, indexed)})));
  EXPECT_FALSE(SamePixels(seven, Thumbnail({FreeGrid(), Record(kMatchStage, renumbered)})));
}

}  // namespace
}  // namespace areagraph
