// Where ag-cut cuts an edge: room changes, doorways, dead ends.
#include "stages/cut/cut_planning.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "tests/stages/cut/straight_edge.h"

namespace areagraph {
namespace {

// Rooms by x: [0, a) room 0, [a, b) none, [b, 100] `last_room`.
std::function<int(const Eigen::Vector2d&)> Rooms(double a, double b, int last_room) {
  return [=](const Eigen::Vector2d& p) { return p.x() < a ? 0 : (p.x() < b ? -1 : last_room); };
}

// A doorway: narrowest at x = 44.
double Doorway(double x) { return x > 40 && x < 48 ? 9 + std::abs(x - 44) * 0.1 : 15; }

constexpr double kRoomWidthPx = 25;

TEST(CutPlanningTest, ShortDoorwayBetweenTwoRoomsLeavesOneCutAtItsNarrowestPoint) {
  const proto::GraphEdge edge = StraightEdge(Doorway);
  const EdgeTrack track(edge);
  const auto pieces = PlanEdgeCuts(track, false, false, kRoomWidthPx, Rooms(41, 47, 1));
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_EQ(pieces[0].room, 0);
  EXPECT_EQ(pieces[1].room, 1);
  EXPECT_NEAR(track.PointAt(pieces[0].end).x(), 44, 1.01);
  EXPECT_NEAR(track.ArcAt(pieces[1].end), 100, 1e-9);
}

TEST(CutPlanningTest, DoorwayBackIntoTheSameRoomIsNotCut) {
  const proto::GraphEdge edge = StraightEdge(Doorway);
  const auto pieces = PlanEdgeCuts(EdgeTrack(edge), false, false, kRoomWidthPx, Rooms(41, 47, 0));
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_EQ(pieces[0].room, 0);
}

TEST(CutPlanningTest, CutIntoALongRoomlessStretchMovesToItsNarrowestPoint) {
  // Room 0 up to x = 30, then no room; narrowest at x = 36.
  const proto::GraphEdge edge =
      StraightEdge([](double x) { return x > 32 && x < 40 ? 8 + std::abs(x - 36) * 0.2 : 12; });
  const EdgeTrack track(edge);
  const auto pieces = PlanEdgeCuts(track, false, false, kRoomWidthPx, Rooms(30, 1000, -1));
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_EQ(pieces[0].room, 0);
  EXPECT_EQ(pieces[1].room, -1);
  EXPECT_NEAR(track.PointAt(pieces[0].end).x(), 36, 1.01);
}

TEST(CutPlanningTest, ShortPieceAtADeadEndJoinsItsNeighbour) {
  const proto::GraphEdge edge = StraightEdge([](double) { return 12.0; });
  // Room 0 up to x = 90, the last 10 px in no room; the target is a dead end.
  const auto pieces = PlanEdgeCuts(EdgeTrack(edge), false, true, kRoomWidthPx, Rooms(90, 1000, -1));
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_EQ(pieces[0].room, 0);
  // The same with a junction at the target is cut.
  EXPECT_EQ(PlanEdgeCuts(EdgeTrack(edge), false, false, kRoomWidthPx, Rooms(90, 1000, -1)).size(),
            2u);
}

TEST(CutPlanningTest, ShortDeadEndEdgeIsNotCutAndTakesTheRoomAtItsJunction) {
  const proto::GraphEdge edge = StraightEdge([](double) { return 12.0; });
  // W wider than the edge: the source is the dead end, the junction is at x = 100.
  const auto pieces = PlanEdgeCuts(EdgeTrack(edge), true, false, 150, Rooms(50, 60, 3));
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_EQ(pieces[0].room, 3);
}

TEST(CutPlanningTest, RoomChangeWithoutGapIsCutWhereItHappens) {
  const proto::GraphEdge edge = StraightEdge([](double) { return 12.0; });
  const EdgeTrack track(edge);
  const auto pieces = PlanEdgeCuts(track, false, false, kRoomWidthPx, Rooms(56.5, 56.5, 2));
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_NEAR(track.PointAt(pieces[0].end).x(), 56.5, 0.01);
  // Half a pixel beside the sites at x = 57, 12 px off the path.
  EXPECT_NEAR(track.ClearanceAt(pieces[0].end), std::hypot(0.5, 12.0), 0.01);
}

}  // namespace
}  // namespace areagraph
