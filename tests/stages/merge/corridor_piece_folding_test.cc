// merge's FOLD_CORRIDOR_PIECES on hand-made cut graphs: a small room
// between two corridor pieces that it opens into over its whole width folds
// into the corridor; one behind a door, a big one, or one across a cut that
// ag-cut closed stays a room.
#include "stages/merge/corridor_piece_folding.h"

#include <gtest/gtest.h>

#include "tests/stages/merge/hand_made_cut_graph.h"

namespace areagraph::testing {
namespace {

constexpr double kResolutionM = 0.05;
constexpr double kMaxM2 = 20;

// An edge from `source` to `target` along x from `x0` to `x1` (px) with a
// constant clearance, its polygon a box `half_width` px either side of the
// path, and jambs `opening_source` / `opening_target` px apart at its ends.
void AddBoxEdge(proto::CutGraph* graph, int source, int target, int room_id, double x0, double x1,
                double half_width, double opening_source, double opening_target) {
  proto::GraphEdge* edge = AddEdge(graph, source, target, room_id, x1 - x0);
  const double xs[3] = {x0, (x0 + x1) / 2, x1};
  for (double x : xs) {
    proto::Point2* point = edge->add_path();
    point->set_x(x);
    point->set_y(0);
    edge->add_clearance_px(half_width);
  }
  const double openings[2] = {opening_source, opening_target};
  for (int s = 0; s < 2; ++s) {
    proto::Point2* left = edge->add_left_sites();
    left->set_x(xs[s == 0 ? 0 : 2]);
    left->set_y(openings[s] / 2);
    proto::Point2* right = edge->add_right_sites();
    right->set_x(xs[s == 0 ? 0 : 2]);
    right->set_y(-openings[s] / 2);
  }
  proto::Ring* ring = edge->mutable_polygon()->mutable_outer();
  for (const auto& [x, y] : std::vector<std::pair<double, double>>{
           {x0, -half_width}, {x1, -half_width}, {x1, half_width}, {x0, half_width}}) {
    proto::Point2* point = ring->add_points();
    point->set_x(x);
    point->set_y(y);
  }
}

// Corridor (0) - small room (1) - corridor (2) along a line: the room is a
// `room_length` px long stretch of the corridor, 40 px (2 m) wide, whose
// openings at its two ends are `opening_left` / `opening_right` px wide; the
// pieces on either side are `side_length` px long.
struct Line {
  proto::CutGraph graph;
  AreaPlan plan;
};
Line CorridorWithRoom(double room_length, double opening_left, double opening_right,
                      bool closed_left = false, double side_length = 200) {
  Line line;
  proto::CutGraph& graph = line.graph;
  const int end_a = AddVertex(&graph, VERTEX_DEAD_END);
  const int left = AddVertex(&graph, VERTEX_PASSAGE);
  const int right = AddVertex(&graph, VERTEX_PASSAGE);
  const int end_b = AddVertex(&graph, VERTEX_DEAD_END);
  const double x1 = side_length, x2 = side_length + room_length;
  AddBoxEdge(&graph, end_a, left, -1, 0, x1, 20, 40, opening_left);
  AddBoxEdge(&graph, left, right, 7, x1, x2, 20, opening_left, opening_right);
  AddBoxEdge(&graph, right, end_b, -1, x2, x2 + side_length, 20, opening_right, 40);
  if (closed_left) {
    proto::PassagePoint* passage = graph.add_passage_points();
    passage->set_vertex(left);
    passage->set_closed_by_cut(true);
  }
  line.plan.areas = {{AREA_DEAD_END, -1, {0}}, {AREA_ROOM, 7, {1}}, {AREA_DEAD_END, -1, {2}}};
  line.plan.area_of_edge = {0, 1, 2};
  return line;
}

TEST(CorridorPieceFoldingTest, SmallRoomOpenAtBothEndsFoldsIntoTheCorridor) {
  // 60 x 40 px = 3 x 2 m, openings as wide as the room (40 px).
  Line line = CorridorWithRoom(60, 40, 40);
  FoldCorridorPieces(line.graph, MeasurePlan(line.graph, line.plan, kResolutionM),
                     ClosedVertices(line.graph), kMaxM2, &line.plan);
  ExpectPlan(line.plan, {{AREA_DEAD_END, -1, {0, 1}}, {AREA_DEAD_END, -1, {2}}}, {0, 0, 1});
}

TEST(CorridorPieceFoldingTest, RoomBehindADoorStays) {
  // The right opening is a 0.9 m door (18 px) in a 2 m wide room: one wide
  // opening only.
  Line line = CorridorWithRoom(60, 40, 18);
  const AreaPlan before = line.plan;
  FoldCorridorPieces(line.graph, MeasurePlan(line.graph, line.plan, kResolutionM),
                     ClosedVertices(line.graph), kMaxM2, &line.plan);
  ExpectPlan(line.plan, {{AREA_DEAD_END, -1, {0}}, {AREA_ROOM, 7, {1}}, {AREA_DEAD_END, -1, {2}}},
             before.area_of_edge);
}

TEST(CorridorPieceFoldingTest, RoomAboveTheLimitStays) {
  // 300 x 40 px = 15 x 2 m = 30 m2, over 20 m2; folds under a 40 m2 limit.
  Line line = CorridorWithRoom(300, 40, 40);
  FoldCorridorPieces(line.graph, MeasurePlan(line.graph, line.plan, kResolutionM),
                     ClosedVertices(line.graph), kMaxM2, &line.plan);
  EXPECT_EQ(line.plan.areas.size(), 3u);
  FoldCorridorPieces(line.graph, MeasurePlan(line.graph, line.plan, kResolutionM),
                     ClosedVertices(line.graph), 40, &line.plan);
  EXPECT_EQ(line.plan.areas.size(), 2u);
}

TEST(CorridorPieceFoldingTest, ClosedCutCountsAsADoor) {
  Line kept = CorridorWithRoom(60, 40, 40, /*closed_left=*/true);
  FoldCorridorPieces(kept.graph, MeasurePlan(kept.graph, kept.plan, kResolutionM),
                     ClosedVertices(kept.graph), kMaxM2, &kept.plan);
  EXPECT_EQ(kept.plan.areas.size(), 3u);
  Line folded = CorridorWithRoom(60, 40, 40, /*closed_left=*/false);
  FoldCorridorPieces(folded.graph, MeasurePlan(folded.graph, folded.plan, kResolutionM),
                     ClosedVertices(folded.graph), kMaxM2, &folded.plan);
  EXPECT_EQ(folded.plan.areas.size(), 2u);
}

TEST(CorridorPieceFoldingTest, SmallRoomBetweenTwoRoomsStays) {
  // The same line with rooms 5 x 2 m on both sides (a suite of small rooms
  // opening into each other): no corridor to fold into.
  Line line = CorridorWithRoom(60, 40, 40, /*closed_left=*/false, /*side_length=*/100);
  line.graph.mutable_edges(0)->set_room_id(5);
  line.graph.mutable_edges(2)->set_room_id(6);
  line.plan.areas = {{AREA_ROOM, 5, {0}}, {AREA_ROOM, 7, {1}}, {AREA_ROOM, 6, {2}}};
  FoldCorridorPieces(line.graph, MeasurePlan(line.graph, line.plan, kResolutionM),
                     ClosedVertices(line.graph), kMaxM2, &line.plan);
  EXPECT_EQ(line.plan.areas.size(), 3u);
}

}  // namespace
}  // namespace areagraph::testing
