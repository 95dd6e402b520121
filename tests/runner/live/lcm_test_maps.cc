#include "tests/runner/live/lcm_test_maps.h"

#include <initializer_list>
#include <utility>

#include "common/error.h"
#include "proto/pipeline_options.pb.h"
#include "stages/match/area_graph_matching.h"

namespace areagraph::testing {
namespace {

void SetRing(proto::Ring* ring, std::initializer_list<std::pair<double, double>> points) {
  for (const auto& [x, y] : points) {
    proto::Point2* point = ring->add_points();
    point->set_x(x);
    point->set_y(y);
  }
}

}  // namespace

proto::GridMap MakeGridMap() {
  proto::GridMap grid;
  grid.set_format_version(1);
  proto::MapFrame* frame = grid.mutable_frame();
  frame->set_resolution_m(0.05);
  frame->set_origin_x_m(-1.5);
  frame->set_origin_y_m(2.0);
  frame->set_origin_yaw_rad(0.25);
  frame->set_width_px(3);
  frame->set_height_px(2);
  grid.set_cells(std::string{proto::CELL_FREE, proto::CELL_OCCUPIED, proto::CELL_UNKNOWN,
                             proto::CELL_UNKNOWN, proto::CELL_OCCUPIED, proto::CELL_FREE});
  return grid;
}

proto::AreaGraph MakeAreaGraph() {
  proto::AreaGraph graph;
  graph.set_format_version(1);
  // As ag-merge writes it with the default options.
  graph.set_robot_width_m(proto::CleanOptions().robot_width_m());
  proto::MapFrame* frame = graph.mutable_frame();
  frame->set_resolution_m(0.05);
  frame->set_origin_x_m(0.5);
  frame->set_origin_y_m(-0.25);
  frame->set_origin_yaw_rad(0.1);
  frame->set_width_px(100);
  frame->set_height_px(80);

  proto::Area* room = graph.add_areas();
  room->set_id(0);
  room->set_kind(proto::AREA_ROOM);
  SetRing(room->mutable_polygon_m()->mutable_outer(), {{0, 0}, {2, 0}, {2, 2}, {0, 2}});
  SetRing(room->mutable_polygon_m()->add_holes(), {{0.5, 0.5}, {1, 0.5}, {1, 1}});
  room->set_area_m2(3.875);
  room->mutable_centroid_m()->set_x(1.0);
  room->mutable_centroid_m()->set_y(1.0);
  room->add_passage_ids(7);

  proto::Area* corridor = graph.add_areas();
  corridor->set_id(1);
  corridor->set_kind(proto::AREA_CORRIDOR);
  SetRing(corridor->mutable_polygon_m()->mutable_outer(), {{2, 0}, {4, 0}, {4, 1}, {2, 1}});
  corridor->set_area_m2(2.0);
  corridor->mutable_centroid_m()->set_x(3.0);
  corridor->mutable_centroid_m()->set_y(0.5);
  corridor->add_passage_ids(7);

  proto::Passage* door = graph.add_passages();
  door->set_id(7);
  door->set_area_a(0);
  door->set_area_b(1);
  door->mutable_point_m()->set_x(2.0);
  door->mutable_point_m()->set_y(0.45);
  door->mutable_segment_m()->mutable_a()->set_x(2.0);
  door->mutable_segment_m()->mutable_a()->set_y(0.0);
  door->mutable_segment_m()->mutable_b()->set_x(2.0);
  door->mutable_segment_m()->mutable_b()->set_y(0.9);
  door->set_width_m(0.9);
  for (const double y : {0.0, 0.45, 0.9}) {
    proto::Point2* point = door->add_border_m();
    point->set_x(2.0);
    point->set_y(y);
  }
  return graph;
}

void MakeTwoVersions(proto::AreaGraph& first, proto::AreaGraph& second) {
  first = MatchAreaGraph(MakeAreaGraph(), nullptr, VersionLink{}, proto::MatchOptions());
  proto::AreaGraph grown = MakeAreaGraph();
  proto::Area* corridor = grown.mutable_areas(1);
  corridor->mutable_polygon_m()->mutable_outer()->clear_points();
  SetRing(corridor->mutable_polygon_m()->mutable_outer(), {{2, 0}, {4, 0}, {4, 1.3}, {2, 1.3}});
  corridor->set_area_m2(2.6);
  proto::Area* dead_end = grown.add_areas();
  dead_end->set_id(2);
  dead_end->set_kind(proto::AREA_DEAD_END);
  SetRing(dead_end->mutable_polygon_m()->mutable_outer(), {{3, 1.3}, {4, 1.3}, {4, 2.3}, {3, 2.3}});
  dead_end->set_area_m2(1.0);
  dead_end->mutable_centroid_m()->set_x(3.5);
  dead_end->mutable_centroid_m()->set_y(1.8);
  grown.mutable_passages(0)->mutable_point_m()->set_y(0.55);
  proto::Passage* opening = grown.add_passages();
  *opening = grown.passages(0);
  opening->set_id(8);
  opening->set_area_a(1);
  opening->set_area_b(2);
  opening->mutable_point_m()->set_x(3.5);
  opening->mutable_point_m()->set_y(1.3);
  corridor->add_passage_ids(8);
  dead_end->add_passage_ids(8);
  second = MatchAreaGraph(grown, &first, VersionLink{"first-key", 2}, proto::MatchOptions());
}

::testing::AssertionResult ThrowsMessage(const std::function<void()>& body,
                                         const std::string& expected) {
  try {
    body();
  } catch (const Error& error) {
    if (std::string(error.what()).find(expected) != std::string::npos) {
      return ::testing::AssertionSuccess();
    }
    return ::testing::AssertionFailure()
           << "message '" << error.what() << "' lacks '" << expected << "'";
  }
  return ::testing::AssertionFailure() << "nothing thrown; expected '" << expected << "'";
}

}  // namespace areagraph::testing
