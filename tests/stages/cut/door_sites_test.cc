// DoorClosingSites on drawn plans: a door in a wall is closed, a gap between
// a wall and a free-standing desk or shelf is not. WallGapSites: a gap beside
// a thin wall end is closed, also when that end is a short piece of wall
// between two doors, not beside a cabinet.
#include "stages/cut/door_sites.h"

#include <gtest/gtest.h>

#include "proto/pipeline_options.pb.h"
#include "tests/support/area_test_support.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using floorplan::FloorPlan;
using floorplan::RectM;
using floorplan::WallDirection;

constexpr double kResolutionM = 0.05;
// Obstacles at least this long are structure (cut.islands.max_length_m's default).
const double kStructureM = proto::CutOptions().islands().max_length_m();

// Two 4 x 4 m rooms side by side, the wall between them at x = 4.5 m with a
// 1.0 m door centred at y = 2.5 m.
FloorPlan TwoRooms() {
  FloorPlan plan(9, 5, kResolutionM);
  floorplan::DrawRoom(plan, {0.5, 0.5, 4, 4});
  floorplan::DrawRoom(plan, {4.5, 0.5, 4, 4});
  floorplan::DrawDoor(plan, 4.5, 2.5, 1.0, WallDirection::kVertical);
  return plan;
}

// An estimate holding one door at (x_m, y_m), `width_m` wide.
proto::RoomWidthEstimate OneDoor(double x_m, double y_m, double width_m) {
  proto::RoomWidthEstimate estimate;
  proto::DetectedWidth* door = estimate.add_doors();
  door->mutable_position()->set_x(x_m / kResolutionM);
  door->mutable_position()->set_y(y_m / kResolutionM);
  door->set_width_m(width_m);
  return estimate;
}

PointList Sites(const FloorPlan& plan, const proto::RoomWidthEstimate& estimate) {
  const proto::CleanedMap map = CleanedMapFromImage(plan.image(), kResolutionM);
  return DoorClosingSites(
      estimate, LabelObstacles(map.cells(), map.frame().width_px(), map.frame().height_px()),
      kResolutionM, kStructureM);
}

TEST(DoorSitesTest, DoorInAWallIsClosedAcrossItsWholeWidth) {
  const PointList sites = Sites(TwoRooms(), OneDoor(4.5, 2.5, 1.0));
  ASSERT_GE(sites.size(), 15u);
  double top = 1e9, bottom = -1e9;
  for (const Eigen::Vector2d& site : sites) {
    EXPECT_NEAR(site.x() * kResolutionM, 4.5, 0.15);
    top = std::min(top, site.y() * kResolutionM);
    bottom = std::max(bottom, site.y() * kResolutionM);
  }
  // From jamb to jamb: the door's 1.0 m less the jamb cells themselves.
  EXPECT_NEAR(top, 2.0, 0.1);
  EXPECT_NEAR(bottom, 3.0, 0.1);
}

TEST(DoorSitesTest, GapBetweenAFreeStandingDeskAndAWallIsNoDoor) {
  // A 1.6 x 0.8 m desk 0.9 m below the left room's top wall: the gap is a
  // narrowing between wider spaces, but one side of it is a small island.
  FloorPlan plan = TwoRooms();
  floorplan::DrawFurniture(plan, {1.5, 1.5, 1.6, 0.8});
  EXPECT_TRUE(Sites(plan, OneDoor(2.3, 1.05, 0.85)).empty());
}

TEST(DoorSitesTest, GapBetweenAWallEndAndAShelfInLineWithItIsNoDoor) {
  // A wall stub from the top wall down to y = 2 m and a free-standing shelf
  // (1.2 x 0.15 m) in line with it below a 0.9 m gap: both sides line up
  // like door jambs, but the shelf is a small island, not wall structure.
  FloorPlan plan = TwoRooms();
  floorplan::DrawFurniture(plan, {2.45, 0.5, 0.15, 1.5});
  floorplan::DrawFurniture(plan, {2.45, 2.9, 0.15, 1.2});
  EXPECT_TRUE(Sites(plan, OneDoor(2.5, 2.45, 0.9)).empty());
  // The same gap with the shelf joined to the bottom wall is a door.
  floorplan::DrawFurniture(plan, {2.45, 2.9, 0.15, 1.6});
  EXPECT_FALSE(Sites(plan, OneDoor(2.5, 2.45, 0.9)).empty());
}

// WallGapSites on the pruned Topology Graph of a plan; with `free_spaces`,
// free cells the gap cannot reach count as non-free past a jamb.
PointList GapSites(const FloorPlan& plan, double max_gap_m, bool short_tips = true,
                   bool free_spaces = false) {
  const proto::CleanedMap map = CleanedMapFromImage(plan.image(), kResolutionM);
  const AreaStages stages = RunAreaStages(map);
  const int width = map.frame().width_px(), height = map.frame().height_px();
  const cv::Mat spaces = LabelFreeSpaces(map.cells(), width, height);
  return WallGapSites(stages.topology, LabelObstacles(map.cells(), width, height), kResolutionM,
                      kStructureM, map.robot_width_m(), max_gap_m, short_tips,
                      free_spaces ? &spaces : nullptr);
}

// WallGapFinder's openings of a plan (short tips on, free spaces off).
std::vector<Opening> GapOpenings(const FloorPlan& plan, double max_gap_m) {
  const proto::CleanedMap map = CleanedMapFromImage(plan.image(), kResolutionM);
  const AreaStages stages = RunAreaStages(map);
  const int width = map.frame().width_px(), height = map.frame().height_px();
  const ObstacleLabels obstacles = LabelObstacles(map.cells(), width, height);
  return WallGapFinder(stages.topology, obstacles, kResolutionM, kStructureM, map.robot_width_m(),
                       max_gap_m, true, nullptr)
      .Openings(0, stages.topology.edges_size());
}

// A 6 x 4 m room whose wall at x = 3 m runs up from the bottom wall to
// y = 2.2 m (m from the top), leaving a 1.7 m gap to the top wall.
FloorPlan PartialWall() {
  FloorPlan plan(7, 5, kResolutionM);
  floorplan::DrawRoom(plan, {0.5, 0.5, 6, 4});
  floorplan::DrawFurniture(plan, {2.95, 2.2, 0.1, 2.3});
  return plan;
}

TEST(DoorSitesTest, GapBetweenAThinWallEndAndAWallIsClosedAlongTheWall) {
  const PointList sites = GapSites(PartialWall(), 2.5);
  ASSERT_GE(sites.size(), 10u);
  for (const Eigen::Vector2d& site : sites) {
    EXPECT_NEAR(site.x() * kResolutionM, 3.0, 0.2);
    EXPECT_GT(site.y() * kResolutionM, 0.5);
    EXPECT_LT(site.y() * kResolutionM, 2.25);
  }
  // Wider than the limit: left open.
  EXPECT_TRUE(GapSites(PartialWall(), 1.5).empty());
  EXPECT_TRUE(GapSites(PartialWall(), 0).empty());
}

TEST(DoorSitesTest, GapToAThinOuterWallWithFreeSpaceBehindIsClosedWithFreeSpaces) {
  // PartialWall with 0.1 m walls and the outside drawn free, as the Area
  // Graph paper's copies of some maps have it: past the top wall's jamb the
  // gap's line leaves the wall after two cells. That free space is not the
  // room's, so with free spaces told apart the wall runs on behind the line.
  FloorPlan plan(7, 5, kResolutionM, 0.1);
  floorplan::DrawRoom(plan, {0.5, 0.5, 6, 4});
  floorplan::DrawFurniture(plan, {2.95, 2.2, 0.1, 2.3});
  plan.image().setTo(floorplan::kFreeGrey, plan.image() == floorplan::kUnknownGrey);
  EXPECT_TRUE(GapSites(plan, 2.5).empty());
  const PointList sites = GapSites(plan, 2.5, true, /*free_spaces=*/true);
  ASSERT_GE(sites.size(), 10u);
  for (const Eigen::Vector2d& site : sites) {
    EXPECT_NEAR(site.x() * kResolutionM, 3.0, 0.2);
    EXPECT_LT(site.y() * kResolutionM, 2.25);
  }
}

TEST(DoorSitesTest, GapBesideACabinetAgainstAWallIsNoWallGap) {
  // The same room without the wall, with a 1.5 x 0.8 m cabinet against the
  // bottom wall: the gap above it ends in the cabinet's face, which is wide
  // across the gap's line, and a corridor-like room's cross-sections end in
  // wall faces.
  FloorPlan plan(7, 5, kResolutionM);
  floorplan::DrawRoom(plan, {0.5, 0.5, 6, 4});
  floorplan::DrawFurniture(plan, {2.25, 2.9, 1.5, 1.6});
  EXPECT_TRUE(GapSites(plan, 3.0).empty());
}

// A 6 x 5 m room divided at x = 3 m by a wall from the bottom wall up to
// y = 3.5 m, a 0.9 m door, a free piece of wall `piece_m` long ending at
// y = 2.6 m, and a second door above it up to the top wall (y = 0.5 m).
FloorPlan WallWithTwoDoors(double piece_m, double piece_thickness_m = 0.1) {
  FloorPlan plan(7, 6, kResolutionM);
  floorplan::DrawRoom(plan, {0.5, 0.5, 6, 5});
  floorplan::DrawFurniture(plan, {2.95, 3.5, 0.1, 2.0});
  floorplan::DrawFurniture(
      plan, {3.0 - 0.5 * piece_thickness_m, 2.6 - piece_m, piece_thickness_m, piece_m});
  return plan;
}

// How many of `sites` lie on the wall's line (x = 3 m) within y0-y1 (m).
int SitesOnTheLine(const PointList& sites, double y0_m, double y1_m) {
  int count = 0;
  for (const Eigen::Vector2d& site : sites) {
    const double x = site.x() * kResolutionM, y = site.y() * kResolutionM;
    count += std::abs(x - 3.0) < 0.2 && y > y0_m && y < y1_m;
  }
  return count;
}

TEST(DoorSitesTest, ShortPieceOfWallBetweenTwoDoorsIsAJamb) {
  // A 1 m piece: both doors are closed with short_tips, neither without
  // (the piece is no structure: it touches no border and is under 4 m).
  const PointList sites = GapSites(WallWithTwoDoors(1.0), 3.5);
  EXPECT_GE(SitesOnTheLine(sites, 2.6, 3.5), 10);  // the lower door
  EXPECT_GE(SitesOnTheLine(sites, 0.5, 1.6), 10);  // the upper door
  EXPECT_EQ(SitesOnTheLine(sites, 0, 6), static_cast<int>(sites.size()));
  EXPECT_TRUE(GapSites(WallWithTwoDoors(1.0), 3.5, /*short_tips=*/false).empty());
}

TEST(DoorSitesTest, DeskOrSpeckInTheWallsLineIsNoJamb) {
  // A 0.9 m deep desk in the piece's place is no thin wall end, and a
  // 0.3 m speck is shorter than kMinWallPieceM: nothing is closed.
  EXPECT_TRUE(GapSites(WallWithTwoDoors(1.0, 0.9), 3.5).empty());
  EXPECT_TRUE(GapSites(WallWithTwoDoors(0.3), 3.5).empty());
}

TEST(DoorSitesTest, AWallGapIsOneOpeningWithItsJambsAndWidth) {
  const std::vector<Opening> openings = GapOpenings(PartialWall(), 2.5);
  ASSERT_EQ(openings.size(), 1u);
  const Opening& gap = openings[0];
  EXPECT_EQ(gap.kind, proto::Opening::WALL_GAP);
  EXPECT_TRUE(gap.closed);
  // From the top wall's face (0.575 m) to the stub's tip (2.2 m).
  EXPECT_NEAR(gap.width_m, 1.6, 0.1);
  ASSERT_TRUE(gap.has_jambs);
  EXPECT_NEAR(gap.position.x() * kResolutionM, 3.0, 0.1);
  EXPECT_GE(gap.lines.size(), 1u);
  // One side is the room's 3 m wide halves, the other as wide.
  EXPECT_GT(std::max(gap.side_a_m, gap.side_b_m), gap.width_m + 0.25);
}

TEST(DoorSitesTest, NoDoorsNoSites) {
  EXPECT_TRUE(Sites(TwoRooms(), proto::RoomWidthEstimate()).empty());
}

}  // namespace
}  // namespace areagraph::testing
