// How ag-render draws an Area Graph: a graph from ag-match is coloured and
// labelled by stable id, so an area looks the same in every version of its map.
#include <gtest/gtest.h>

#include "tools/render/artifact_drawing.h"
#include "tools/render/canvas.h"

namespace areagraph {
namespace {

// A 20 x 10 cell map split into two 10 x 10 areas, with ids 0 and 1.
proto::AreaGraph TwoSquares() {
  proto::AreaGraph graph;
  proto::MapFrame* frame = graph.mutable_frame();
  frame->set_resolution_m(0.1);
  frame->set_width_px(20);
  frame->set_height_px(10);
  for (int i = 0; i < 2; ++i) {
    proto::Area* area = graph.add_areas();
    area->set_id(i);
    for (const auto& [x, y] : {std::pair{0, 0}, {10, 0}, {10, 10}, {0, 10}}) {
      proto::Point2* point = area->mutable_polygon_px()->mutable_outer()->add_points();
      point->set_x(x + 10 * i);
      point->set_y(y);
    }
    area->mutable_centroid_m()->set_x(0.5 + i);
    area->mutable_centroid_m()->set_y(0.5);
  }
  return graph;
}

// The colour drawn in the left area, away from its label.
cv::Vec3b LeftAreaColour(const proto::AreaGraph& graph) {
  Canvas canvas(std::string(200, static_cast<char>(proto::CELL_FREE)), 20, 10, 4);
  DrawAreaGraph(graph, canvas);
  return canvas.image().at<cv::Vec3b>(4, 4);
}

TEST(AreaGraphDrawingTest, AMatchedGraphIsColouredByStableId) {
  proto::AreaGraph matched = TwoSquares();
  matched.mutable_areas(0)->set_stable_id(5);
  matched.mutable_areas(1)->set_stable_id(2);
  matched.mutable_version()->set_number(3);
  proto::AreaGraph numbered_five = TwoSquares();
  numbered_five.mutable_areas(0)->set_id(5);
  const proto::AreaGraph unmatched = TwoSquares();

  EXPECT_EQ(LeftAreaColour(matched), LeftAreaColour(numbered_five));
  EXPECT_NE(LeftAreaColour(matched), LeftAreaColour(unmatched));
}

}  // namespace
}  // namespace areagraph
