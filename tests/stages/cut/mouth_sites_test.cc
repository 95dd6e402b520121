// MouthOpenings on drawn plans: a room open along a whole side to a hall is
// closed along the hall's wall line; a corridor meeting the hall, or a gap in
// a straight wall, is no mouth.
#include "stages/cut/mouth_sites.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "proto/pipeline_options.pb.h"
#include "tests/support/area_test_support.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using floorplan::FloorPlan;
using floorplan::WallDirection;

constexpr double kResolutionM = 0.05;
// Obstacles at least this long are structure (cut.islands.max_length_m's default).
const double kStructureM = proto::CutOptions().islands().max_length_m();

std::vector<Opening> Mouths(const FloorPlan& plan, double max_mouth_m) {
  const proto::CleanedMap map = CleanedMapFromImage(plan.image(), kResolutionM);
  const int width = map.frame().width_px(), height = map.frame().height_px();
  const cv::Mat spaces = LabelFreeSpaces(map.cells(), width, height);
  return MouthOpenings(LabelObstacles(map.cells(), width, height), kResolutionM, kStructureM,
                       map.robot_width_m(), max_mouth_m, &spaces);
}

// A 12 x 8 m hall with a bay of `bay_width_m` x 4 m above it, open along its
// whole width: the bay's side walls end on the line of the hall's top wall.
FloorPlan HallWithBay(double bay_width_m = 5) {
  FloorPlan plan(14, 14, kResolutionM);
  floorplan::DrawRoom(plan, {1, 5, 12, 8});
  floorplan::DrawRoom(plan, {4, 1, bay_width_m, 4});
  floorplan::DrawDoor(plan, 4 + bay_width_m / 2, 5, bay_width_m - 0.15, WallDirection::kHorizontal);
  return plan;
}

TEST(MouthSitesTest, MouthOfABayIsClosedAlongTheWallsLine) {
  const std::vector<Opening> mouths = Mouths(HallWithBay(), 10);
  ASSERT_EQ(mouths.size(), 1u);
  const Opening& mouth = mouths[0];
  EXPECT_EQ(mouth.kind, proto::Opening::MOUTH);
  EXPECT_TRUE(mouth.closed);
  EXPECT_NEAR(mouth.width_m, 4.85, 0.15);
  const PointList sites = ClosingSites(mouths);
  ASSERT_GE(sites.size(), 50u);
  double left = 1e9, right = -1e9;
  for (const Eigen::Vector2d& site : sites) {
    // Every line lies within a wall's thickness (0.6 m) of the hall's wall
    // line, across the bay's whole width.
    EXPECT_GT(site.y() * kResolutionM, 4.35);
    EXPECT_LT(site.y() * kResolutionM, 5.15);
    left = std::min(left, site.x() * kResolutionM);
    right = std::max(right, site.x() * kResolutionM);
  }
  EXPECT_LT(left, 4.3);
  EXPECT_GT(right, 8.7);
  // Wider than the limit, or with mouths off, it stays open.
  EXPECT_TRUE(Mouths(HallWithBay(), 4.0).empty());
  EXPECT_TRUE(Mouths(HallWithBay(), 0).empty());
}

TEST(MouthSitesTest, ABayWiderThanTheCorridorInFrontOfItIsFound) {
  // A 2 m corridor with a 6 x 4 m bay above it: the Topology Graph never
  // crosses that mouth jamb to jamb (its nearest obstacle is the corridor's
  // far wall), which is why mouths are found from the walls.
  FloorPlan plan(16, 8, kResolutionM);
  floorplan::DrawRoom(plan, {1, 5, 14, 2});
  floorplan::DrawRoom(plan, {5, 1, 6, 4});
  floorplan::DrawDoor(plan, 8, 5, 5.85, WallDirection::kHorizontal);
  const std::vector<Opening> mouths = Mouths(plan, 10);
  ASSERT_EQ(mouths.size(), 1u);
  EXPECT_NEAR(mouths[0].width_m, 5.85, 0.15);
}

// A 14 x 8 m hall with a side corridor of 2 x `depth_m` above it, open
// along its whole width.
FloorPlan HallWithSideCorridor(double depth_m) {
  FloorPlan plan(16, depth_m + 11, kResolutionM);
  floorplan::DrawRoom(plan, {1, depth_m + 1, 14, 8});
  floorplan::DrawRoom(plan, {7, 1, 2, depth_m});
  floorplan::DrawDoor(plan, 8, depth_m + 1, 1.85, WallDirection::kHorizontal);
  return plan;
}

TEST(MouthSitesTest, MouthOfACorridorStaysOpen) {
  // 12 m deep, more than four times its width: a corridor meeting the hall.
  EXPECT_TRUE(Mouths(HallWithSideCorridor(12), 10).empty());
  // 5 m deep: a room open along its narrow side.
  EXPECT_EQ(Mouths(HallWithSideCorridor(5), 10).size(), 1u);
}

TEST(MouthSitesTest, WideGapInAStraightWallIsNoMouth) {
  // Two halls side by side, the wall between them open for 4.85 m in its
  // middle: no side walls behind the jambs.
  FloorPlan plan(14, 14, kResolutionM);
  floorplan::DrawRoom(plan, {1, 1, 12, 6});
  floorplan::DrawRoom(plan, {1, 7, 12, 6});
  floorplan::DrawDoor(plan, 7, 7, 4.85, WallDirection::kHorizontal);
  EXPECT_TRUE(Mouths(plan, 10).empty());
}

}  // namespace
}  // namespace areagraph::testing
