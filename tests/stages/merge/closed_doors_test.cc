// Closed doors (ClosedVertices) on hand-made cut graphs: two rooms that room
// joining (or furniture-gap joining) would join stay apart where ag-cut
// marked the cut between them closed, unless both are shaped like corridors.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "proto/pipeline_options.pb.h"
#include "stages/merge/furniture_gap_joining.h"
#include "stages/merge/room_joining.h"
#include "tests/stages/merge/hand_made_cut_graph.h"

namespace areagraph::testing {
namespace {

// 5 cm cells: room joining looks 30 px into each room, past the 10 px edges.
constexpr double kResolutionM = 0.05;

void SetPoint(proto::Point2* point, double x, double y) {
  point->set_x(x);
  point->set_y(y);
}

// A `length` x 20 px rectangle from x = `x0` (a room's shape).
proto::Polygon Rectangle(double x0, double length) {
  proto::Polygon polygon;
  for (const auto& [x, y] : {std::pair{x0, -10.0}, std::pair{x0 + length, -10.0},
                             std::pair{x0 + length, 10.0}, std::pair{x0, 10.0}}) {
    SetPoint(polygon.mutable_outer()->add_points(), x, y);
  }
  return polygon;
}

// Two rooms along y = 0, 20 px wide, that meet at the cut vertex 1 (x = 20)
// through a 20 px opening as wide as the space beside it: each room's edge
// runs in 2 px steps from its far end to the cut, with sites 10 px either
// side of every step. Rooms `room_length` px long; the cut marked closed
// when `closed`. A room-less edge from each room's far end (edges 2 and 3)
// leads to another area, so that each room meets others at two places.
proto::CutGraph TwoRooms(double room_length, bool closed) {
  proto::CutGraph graph;
  AddVertex(&graph, VERTEX_JUNCTION, 10, 20 - room_length, 0);
  const int cut = AddVertex(&graph, VERTEX_PASSAGE, 10, 20, 0);
  AddVertex(&graph, VERTEX_JUNCTION, 10, 20 + room_length, 0);
  for (const int room : {0, 1}) {
    proto::GraphEdge* edge = AddEdge(&graph, room == 0 ? 0 : 2, cut, room, room_length);
    const double step = room == 0 ? 2 : -2;
    const double start = room == 0 ? 20 - room_length : 20 + room_length;
    const int steps = static_cast<int>(room_length / 2);
    for (int i = 0; i <= steps; ++i) {
      const double x = start + i * step;
      SetPoint(edge->add_path(), x, 0);
      edge->add_clearance_px(10);
      if (i == 0) continue;
      SetPoint(edge->add_left_sites(), x, 10);
      SetPoint(edge->add_right_sites(), x, -10);
    }
    *edge->mutable_polygon() = Rectangle(room == 0 ? 20 - room_length : 20, room_length);
  }
  for (const int end : {0, 2}) {
    const double x = graph.vertices(end).position().x();
    const int side = AddVertex(&graph, VERTEX_DEAD_END, 5, x, 30);
    proto::GraphEdge* edge = AddEdge(&graph, end, side, -1, 30);
    SetPoint(edge->add_path(), x, 0);
    SetPoint(edge->add_path(), x, 30);
    SetPoint(edge->add_left_sites(), x - 5, 15);
    SetPoint(edge->add_right_sites(), x + 5, 15);
    edge->add_clearance_px(5);
    edge->add_clearance_px(5);
  }
  *graph.add_room_shapes() = Rectangle(20 - room_length, room_length);
  *graph.add_room_shapes() = Rectangle(20, room_length);
  proto::PassagePoint* passage = graph.add_passage_points();
  passage->set_id(0);
  passage->set_vertex(cut);
  SetPoint(passage->mutable_position(), 20, 0);
  passage->set_closed_by_cut(closed);
  return graph;
}

// 1 when the two rooms (edges 0 and 1) are one area, else 2.
size_t Rooms(const AreaPlan& plan) { return plan.area_of_edge[0] == plan.area_of_edge[1] ? 1 : 2; }

size_t RoomsAfterJoining(const proto::CutGraph& graph) {
  AreaPlan plan = AssignAreas(graph);
  EXPECT_EQ(Rooms(plan), 2u);
  JoinRoomsWithoutDoors(graph, MeasurePlan(graph, plan, kResolutionM), ClosedVertices(graph),
                        &plan);
  return Rooms(plan);
}

TEST(ClosedDoorsTest, RoomJoiningJoinsRoomsAtAnOpenCut) {
  EXPECT_EQ(RoomsAfterJoining(TwoRooms(20, false)), 1u);
}

TEST(ClosedDoorsTest, RoomJoiningKeepsRoomsApartAtAClosedCut) {
  EXPECT_EQ(RoomsAfterJoining(TwoRooms(20, true)), 2u);
}

TEST(ClosedDoorsTest, TwoCorridorShapedRoomsJoinAtAClosedCut) {
  // 130 x 20 px (6.5 x 1 m): more than kCorridorElongation squares of the
  // 20 px width, and each meets others at two places: corridors.
  EXPECT_EQ(RoomsAfterJoining(TwoRooms(130, true)), 1u);
  // 60 x 20 px is three squares: rooms, kept apart.
  EXPECT_EQ(RoomsAfterJoining(TwoRooms(60, true)), 2u);
}

TEST(ClosedDoorsTest, FurnitureGapJoiningKeepsRoomsApartAtAClosedCut) {
  // An island under the opening's left jamb (20, 10).
  cv::Mat islands = cv::Mat::zeros(40, 40, CV_8U);
  islands.at<uint8_t>(10, 20) = 1;
  auto rooms = [&](bool closed) {
    const proto::CutGraph graph = TwoRooms(20, closed);
    AreaPlan plan = AssignAreas(graph);
    JoinAreasAtFurnitureGaps(graph, MeasurePlan(graph, plan, kResolutionM), ClosedVertices(graph),
                             islands, proto::FoldCorridorPiecesOptions().below_m2(), &plan);
    return Rooms(plan);
  };
  EXPECT_EQ(rooms(false), 1u);
  EXPECT_EQ(rooms(true), 2u);
}

}  // namespace
}  // namespace areagraph::testing
