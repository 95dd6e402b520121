// merge's JOIN_POROUS_BORDERS on hand-made cut graphs: two rooms that
// meet at three graph vertices, one of them a gap too narrow to walk
// through, are one room (clutter standing in it); two doors, three wide
// openings, or a narrow gap that ag-cut closed as a door leave them apart.
#include "stages/merge/porous_border_joining.h"

#include <gtest/gtest.h>

#include <vector>

#include "tests/stages/merge/hand_made_cut_graph.h"

namespace areagraph::testing {
namespace {

constexpr double kResolutionM = 0.05;
constexpr double kNarrowGapPx = 10;  // 0.5 m

// Room 1 and room 2 meet at one vertex per entry of `openings_px` (the width
// of the opening there); room 1's edge i runs from its centre to vertex i,
// room 2's from vertex i to its centre. `closed` marks vertices that ag-cut
// closed on purpose.
struct TwoRooms {
  proto::CutGraph graph;
  AreaPlan plan;
};
TwoRooms RoomsMeetingAt(const std::vector<double>& openings_px,
                        const std::vector<bool>& closed = {}) {
  TwoRooms rooms;
  proto::CutGraph& graph = rooms.graph;
  const int centre_a = AddVertex(&graph, VERTEX_JUNCTION, 40, 0, 0);
  const int centre_b = AddVertex(&graph, VERTEX_JUNCTION, 40, 200, 0);
  AreaPlan::Area a{AREA_ROOM, 1, {}}, b{AREA_ROOM, 2, {}};
  for (size_t i = 0; i < openings_px.size(); ++i) {
    const double y = 60.0 * static_cast<double>(i);
    const int vertex = AddVertex(&graph, VERTEX_PASSAGE, openings_px[i] / 2, 100, y);
    if (i < closed.size() && closed[i]) {
      proto::PassagePoint* passage = graph.add_passage_points();
      passage->set_vertex(vertex);
      passage->set_closed_by_cut(true);
    }
    for (const bool first : {true, false}) {
      proto::GraphEdge* edge = first ? AddEdge(&graph, centre_a, vertex, 1, 100)
                                     : AddEdge(&graph, vertex, centre_b, 2, 100);
      proto::Point2* left = edge->add_left_sites();
      left->set_x(100);
      left->set_y(y + openings_px[i] / 2);
      proto::Point2* right = edge->add_right_sites();
      right->set_x(100);
      right->set_y(y - openings_px[i] / 2);
      (first ? a : b).edges.push_back(edge->id());
      rooms.plan.area_of_edge.push_back(first ? 0 : 1);
    }
  }
  rooms.plan.areas = {a, b};
  return rooms;
}

TEST(PorousBorderJoiningTest, ThreeOpeningsOneTooNarrowForADoorJoin) {
  // 0.4 m between two shelves, and two 1 m gaps.
  TwoRooms rooms = RoomsMeetingAt({8, 20, 20});
  JoinAtPorousBorders(rooms.graph, MeasurePlan(rooms.graph, rooms.plan, kResolutionM),
                      ClosedVertices(rooms.graph), kNarrowGapPx, &rooms.plan);
  ExpectPlan(rooms.plan, {{AREA_ROOM, 1, {0, 1, 2, 3, 4, 5}}}, {0, 0, 0, 0, 0, 0});
}

TEST(PorousBorderJoiningTest, TwoOpeningsStayApart) {
  // A wall with a door and a narrow gap: no more than a wall with two doors.
  TwoRooms rooms = RoomsMeetingAt({8, 8});
  JoinAtPorousBorders(rooms.graph, MeasurePlan(rooms.graph, rooms.plan, kResolutionM),
                      ClosedVertices(rooms.graph), kNarrowGapPx, &rooms.plan);
  EXPECT_EQ(rooms.plan.areas.size(), 2u);
}

TEST(PorousBorderJoiningTest, ThreeDoorWideOpeningsStayApart) {
  // A big room with three doors into its neighbour (a meeting room opening wide into an office).
  TwoRooms rooms = RoomsMeetingAt({20, 20, 21});
  JoinAtPorousBorders(rooms.graph, MeasurePlan(rooms.graph, rooms.plan, kResolutionM),
                      ClosedVertices(rooms.graph), kNarrowGapPx, &rooms.plan);
  EXPECT_EQ(rooms.plan.areas.size(), 2u);
}

TEST(PorousBorderJoiningTest, ClosedCutDoesNotCount) {
  TwoRooms kept = RoomsMeetingAt({8, 20, 20}, {false, true, false});
  JoinAtPorousBorders(kept.graph, MeasurePlan(kept.graph, kept.plan, kResolutionM),
                      ClosedVertices(kept.graph), kNarrowGapPx, &kept.plan);
  EXPECT_EQ(kept.plan.areas.size(), 2u);
  TwoRooms joined = RoomsMeetingAt({8, 20, 20}, {false, false, false});
  JoinAtPorousBorders(joined.graph, MeasurePlan(joined.graph, joined.plan, kResolutionM),
                      ClosedVertices(joined.graph), kNarrowGapPx, &joined.plan);
  EXPECT_EQ(joined.plan.areas.size(), 1u);
}

}  // namespace
}  // namespace areagraph::testing
