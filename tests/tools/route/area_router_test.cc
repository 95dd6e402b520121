#include "tools/route/area_router.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/error.h"
#include "tests/tools/route/route_test_graphs.h"

namespace areagraph {
namespace {

using testing::AddArea;
using testing::AddPassage;
using testing::TwoRoomsWithDoor;

double PolylineLength(const std::vector<Vec2>& polyline) {
  double length = 0;
  for (size_t i = 0; i + 1 < polyline.size(); ++i) length += (polyline[i + 1] - polyline[i]).norm();
  return length;
}

Route FindOrFail(const AreaRouter& router, const Vec2& start, const Vec2& goal) {
  const RouteAnswer answer = router.FindRoute(start, goal);
  EXPECT_TRUE(answer.route) << answer.no_route_reason;
  return answer.route.value_or(Route{});
}

TEST(AreaRouterTest, GoesStraightThroughADoorAtAnyPointOfIt) {
  const AreaRouter router(TwoRoomsWithDoor());
  // Through the door's middle, and near its lower end: both straight.
  for (const double y : {2.0, 1.6}) {
    const Route route = FindOrFail(router, {1, y}, {9, y});
    EXPECT_NEAR(route.length_m, 8.0, 1e-9) << "y " << y;
    EXPECT_EQ(route.polyline.size(), 2u);
    EXPECT_EQ(route.areas, (std::vector<int>{0, 1}));
    EXPECT_EQ(route.passages, (std::vector<int>{0}));
  }
  // Diagonally through the door: still one straight line.
  EXPECT_NEAR(FindOrFail(router, {1, 0.5}, {9, 3.5}).length_m, std::hypot(8.0, 3.0), 1e-9);
}

TEST(AreaRouterTest, BendsAtTheDoorsJambWhenTheWallIsInTheWay) {
  const AreaRouter router(TwoRoomsWithDoor());
  const Route route = FindOrFail(router, {1, 0.5}, {9, 0.5});
  EXPECT_NEAR(route.length_m, 2 * std::hypot(4.0, 1.0), 1e-9);
  ASSERT_EQ(route.polyline.size(), 3u);
  EXPECT_EQ(route.polyline[1], Vec2(5, 1.5));
  EXPECT_NEAR(PolylineLength(route.polyline), route.length_m, 1e-12);
}

TEST(AreaRouterTest, GoesAroundAHoleAlongItsCorners) {
  proto::AreaGraph graph;
  AddArea(&graph, {{0, 0}, {10, 0}, {10, 4}, {0, 4}}, {{{3, 0.5}, {7, 0.5}, {7, 3.5}, {3, 3.5}}});
  const AreaRouter router(graph);
  const Route route = FindOrFail(router, {1, 2}, {9, 2});
  EXPECT_NEAR(route.length_m, 2 * std::hypot(2.0, 1.5) + 4, 1e-9);
  EXPECT_EQ(route.polyline.size(), 4u);
  EXPECT_FALSE(router.FindRoute({5, 2}, {1, 1}).route) << "a start 1.5 m inside the hole";
}

TEST(AreaRouterTest, BendsAroundBothCornersOfAUShapedRoom) {
  proto::AreaGraph graph;
  AddArea(&graph, {{0, 0}, {6, 0}, {6, 5}, {4, 5}, {4, 2}, {2, 2}, {2, 5}, {0, 5}});
  const AreaRouter router(graph);
  const Route route = FindOrFail(router, {1, 4}, {5, 4});
  ASSERT_EQ(route.polyline.size(), 4u);
  EXPECT_EQ(route.polyline[1], Vec2(2, 2));
  EXPECT_EQ(route.polyline[2], Vec2(4, 2));
  EXPECT_NEAR(route.length_m, 2 * std::hypot(1.0, 2.0) + 2, 1e-9);
}

// A = [0, 2]², D = [2, 4]² touch only at (2, 2); both open into B =
// [2, 4] x [0, 2], A through x = 2 at y in [0.5, 1.5], D through y = 2 at x
// in [2.5, 3.5].
proto::AreaGraph CornerPinch() {
  proto::AreaGraph graph;
  const int a = AddArea(&graph, {{0, 0}, {2, 0}, {2, 0.5}, {2, 1.5}, {2, 2}, {0, 2}});
  const int b =
      AddArea(&graph, {{2, 0}, {4, 0}, {4, 2}, {3.5, 2}, {2.5, 2}, {2, 2}, {2, 1.5}, {2, 0.5}});
  const int d = AddArea(&graph, {{2, 2}, {2.5, 2}, {3.5, 2}, {4, 2}, {4, 4}, {2, 4}});
  AddPassage(&graph, a, b, {{2, 0.5}, {2, 1.5}});
  AddPassage(&graph, b, d, {{2.5, 2}, {3.5, 2}});
  return graph;
}

TEST(AreaRouterTest, DoesNotSlipThroughAPointWhereTwoAreasTouch) {
  const AreaRouter router(CornerPinch());
  EXPECT_FALSE(router.free_space().SegmentIsFree({1, 1}, {3, 3}));
  const Route route = FindOrFail(router, {1, 1}, {3, 3});
  EXPECT_NEAR(route.length_m, std::hypot(1.0, 0.5) + std::hypot(0.5, 0.5) + std::hypot(0.5, 1.0),
              1e-9);
  EXPECT_EQ(route.areas, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(route.passages, (std::vector<int>{0, 1}));
}

TEST(AreaRouterTest, DoesNotSlideAlongAWallPastTheEndOfAWallBetweenTwoAreas) {
  // Rooms A = [0, 2]² and B = [2, 4] x [0, 2] share the wall x = 2, no door;
  // each opens into the corridor C = [0, 4] x [2, 3] above.
  proto::AreaGraph graph;
  const int a = AddArea(&graph, {{0, 0}, {2, 0}, {2, 2}, {1.5, 2}, {0.5, 2}, {0, 2}});
  const int b = AddArea(&graph, {{2, 0}, {4, 0}, {4, 2}, {3.5, 2}, {2.5, 2}, {2, 2}});
  const int c = AddArea(
      &graph, {{0, 2}, {0.5, 2}, {1.5, 2}, {2, 2}, {2.5, 2}, {3.5, 2}, {4, 2}, {4, 3}, {0, 3}});
  AddPassage(&graph, a, c, {{0.5, 2}, {1.5, 2}});
  AddPassage(&graph, b, c, {{2.5, 2}, {3.5, 2}});
  const AreaRouter router(graph);
  EXPECT_FALSE(router.free_space().SegmentIsFree({1, 0}, {3, 0})) << "along the outer wall";
  EXPECT_FALSE(router.free_space().SegmentIsFree({1, 1}, {3, 1})) << "through the wall";
  EXPECT_TRUE(router.free_space().SegmentIsFree({0.5, 0}, {1.5, 0})) << "along a wall";
  const Route route = FindOrFail(router, {1, 1}, {3, 1});
  EXPECT_EQ(route.areas, (std::vector<int>{a, c, b}));
  // Up through A's door at its right jamb, across, down through B's left jamb.
  EXPECT_NEAR(route.length_m, 2 * std::hypot(0.5, 1.0) + 1, 1e-9);
}

TEST(AreaRouterTest, KeepsToOneSideWhenSlidingAlongAWallBetweenTwoAreas) {
  // A = [2, 4] x [2, 4]; B, an L below and left of it, shares the wall x = 2
  // (y 2..3) and y = 2 (x 2..3.5) with it; the door is y = 2, x 3.5..4.
  proto::AreaGraph graph;
  const int a = AddArea(&graph, {{2, 2}, {3.5, 2}, {4, 2}, {4, 4}, {2, 4}, {2, 3}});
  const int b = AddArea(&graph, {{0, 0}, {4, 0}, {4, 2}, {3.5, 2}, {2, 2}, {2, 3}, {0, 3}});
  AddPassage(&graph, a, b, {{3.5, 2}, {4, 2}});
  const AreaRouter router(graph);
  // Down A's outer wall, on along the wall to B: that would come out on B's side.
  EXPECT_FALSE(router.free_space().SegmentIsFree({2, 3.5}, {2, 1}));
  EXPECT_TRUE(router.free_space().SegmentIsFree({2, 3.5}, {2, 2.5}));
  const Route route = FindOrFail(router, {3, 3.5}, {1, 2.5});
  EXPECT_NEAR(route.length_m, std::hypot(0.5, 1.5) + 1.5 + std::hypot(1.0, 0.5), 1e-9);
  EXPECT_EQ(route.areas, (std::vector<int>{a, b}));
}

TEST(AreaRouterTest, BendsAtAPassagesEndOnlyOnThePassagesSide) {
  // A = [0, 2]² and B = [2, 4] x [0, 2] meet at a door x = 2, y 1..2, whose
  // upper end touches C = [0, 4] x [2, 3] above them; C opens into B only,
  // at y = 2, x 3.5..4.
  proto::AreaGraph graph;
  const int a = AddArea(&graph, {{0, 0}, {2, 0}, {2, 1}, {2, 2}, {0, 2}});
  const int b = AddArea(&graph, {{2, 0}, {4, 0}, {4, 2}, {3.5, 2}, {2, 2}, {2, 1}});
  const int c = AddArea(&graph, {{0, 2}, {2, 2}, {3.5, 2}, {4, 2}, {4, 3}, {0, 3}});
  AddPassage(&graph, a, b, {{2, 1}, {2, 2}});
  AddPassage(&graph, b, c, {{4, 2}, {3.5, 2}});
  const AreaRouter router(graph);
  // Not from C round the door's end into A: through C's door and B.
  const Route route = FindOrFail(router, {1, 2.5}, {1, 1.5});
  EXPECT_NEAR(route.length_m, 2 * std::hypot(2.5, 0.5), 1e-9);
  EXPECT_EQ(route.areas, (std::vector<int>{c, b, a}));
  EXPECT_EQ(route.passages, (std::vector<int>{1, 0}));
}

TEST(AreaRouterTest, AreasThatNoPassageJoinsHaveNoRoute) {
  proto::AreaGraph graph = TwoRoomsWithDoor();
  graph.clear_passages();
  const AreaRouter router(graph);
  const RouteAnswer answer = router.FindRoute({1, 2}, {9, 2});
  EXPECT_FALSE(answer.route);
  EXPECT_EQ(answer.no_route_reason, "no passages join the start's area to the goal's");
  EXPECT_FALSE(router.free_space().SegmentIsFree({1, 2}, {9, 2}));
}

TEST(AreaRouterTest, AnEndWithinOneMetreOfAnAreaStartsFromItsNearestPoint) {
  const AreaRouter router(TwoRoomsWithDoor());
  const Route route = FindOrFail(router, {-0.5, 2}, {10.25, 2});
  ASSERT_EQ(route.polyline.size(), 4u);
  EXPECT_EQ(route.polyline.front(), Vec2(-0.5, 2));
  EXPECT_EQ(route.polyline[1], Vec2(0, 2));
  EXPECT_EQ(route.polyline[2], Vec2(10, 2));
  EXPECT_NEAR(route.length_m, 10.75, 1e-9);

  const RouteAnswer far = router.FindRoute({-1.5, 2}, {9, 2});
  EXPECT_FALSE(far.route);
  EXPECT_EQ(far.no_route_reason, "the start (-1.5, 2) is more than 1 m from every area");
  EXPECT_THROW(router.FindRoute({NAN, 0}, {1, 1}), InputError);
}

TEST(AreaRouterTest, RefusesAGraphWithoutPolygonsInMetres) {
  proto::AreaGraph graph;
  graph.add_areas()->set_id(0);
  try {
    const AreaRouter router(graph);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(),
                 "area 0 has no polygon in metres; make the Area Graph again with this areagraph");
  }
}

}  // namespace
}  // namespace areagraph
