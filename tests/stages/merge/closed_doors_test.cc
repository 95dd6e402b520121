// merge.keep_closed_doors on hand-made cut graphs: two rooms that room
// joining (or furniture-gap joining) would join stay apart where ag-cut
// marked the cut between them closed, unless both are shaped like corridors.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "stages/merge/furniture_gap_joining.h"
#include "stages/merge/room_joining.h"
#include "tests/stages/merge/hand_made_cut_graph.h"

namespace areagraph::testing {
namespace {

// 0.5 m cells: room joining looks 3 px into each room.
constexpr double kResolutionM = 0.5;

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

// Two rooms along y = 0 that meet at the cut vertex 1 (x = 20) through a
// 20 px opening as wide as the space beside it: the sites of both edges'
// last segments stand at x = 20, 10 px either side. Rooms `room_length` px
// long; the cut marked closed when `closed`.
proto::CutGraph TwoRooms(double room_length, bool closed) {
  proto::CutGraph graph;
  AddVertex(&graph, VERTEX_JUNCTION, 10, 10, 0);
  const int cut = AddVertex(&graph, VERTEX_PASSAGE, 10, 20, 0);
  AddVertex(&graph, VERTEX_JUNCTION, 10, 30, 0);
  for (const int room : {0, 1}) {
    proto::GraphEdge* edge = AddEdge(&graph, room == 0 ? 0 : 2, cut, room, 10);
    SetPoint(edge->add_path(), room == 0 ? 10 : 30, 0);
    SetPoint(edge->add_path(), 20, 0);
    SetPoint(edge->add_left_sites(), 20, 10);
    SetPoint(edge->add_right_sites(), 20, -10);
    edge->add_clearance_px(10);
    edge->add_clearance_px(10);
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

size_t RoomsAfterJoining(const proto::CutGraph& graph, bool keep_closed_doors) {
  AreaPlan plan = AssignAreas(graph);
  EXPECT_EQ(plan.areas.size(), 2u);
  JoinRoomsWithoutDoors(graph, kResolutionM, keep_closed_doors, &plan);
  return plan.areas.size();
}

TEST(ClosedDoorsTest, RoomJoiningJoinsRoomsAtAnOpenCut) {
  EXPECT_EQ(RoomsAfterJoining(TwoRooms(20, false), true), 1u);
}

TEST(ClosedDoorsTest, RoomJoiningKeepsRoomsApartAtAClosedCut) {
  EXPECT_EQ(RoomsAfterJoining(TwoRooms(20, true), true), 2u);
  // With the option off, the mark is ignored.
  EXPECT_EQ(RoomsAfterJoining(TwoRooms(20, true), false), 1u);
}

TEST(ClosedDoorsTest, TwoCorridorShapedRoomsJoinAtAClosedCut) {
  // 130 x 20 px: more than kCorridorElongation squares of the 20 px width.
  EXPECT_EQ(RoomsAfterJoining(TwoRooms(130, true), true), 1u);
  // 100 x 20 px is five squares: rooms, kept apart.
  EXPECT_EQ(RoomsAfterJoining(TwoRooms(100, true), true), 2u);
}

TEST(ClosedDoorsTest, FurnitureGapJoiningKeepsRoomsApartAtAClosedCut) {
  // An island under the opening's left jamb (20, 10).
  cv::Mat islands = cv::Mat::zeros(40, 40, CV_8U);
  islands.at<uint8_t>(10, 20) = 1;
  auto rooms = [&](bool closed, bool keep) {
    const proto::CutGraph graph = TwoRooms(20, closed);
    AreaPlan plan = AssignAreas(graph);
    JoinAreasAtFurnitureGaps(graph, islands, kResolutionM, keep, /*corridor_clutter=*/true, &plan);
    return plan.areas.size();
  };
  EXPECT_EQ(rooms(false, true), 1u);
  EXPECT_EQ(rooms(true, true), 2u);
  EXPECT_EQ(rooms(true, false), 1u);
}

}  // namespace
}  // namespace areagraph::testing
