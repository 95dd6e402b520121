// EstimateRoomWidth on drawn floor plans whose door and corridor widths are
// known: the estimates, and the W that the paper's rule gives from them.
#include "stages/cut/width_estimate.h"

#include <gtest/gtest.h>

#include "tests/support/area_test_support.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using floorplan::DrawDoor;
using floorplan::DrawRoom;
using floorplan::FloorPlan;
using floorplan::WallDirection;

// Three 3.5 m wide rooms above a 12 m corridor that is `corridor_m` between
// wall centres, each room joined to it by a door `door_m` wide.
FloorPlan RoomsAlongACorridor(double door_m, double corridor_m) {
  FloorPlan plan(12, 5.5 + corridor_m);
  for (int i = 0; i < 3; ++i) DrawRoom(plan, {0.5 + i * 3.5, 0.5, 3.5, 4.5});
  DrawRoom(plan, {0.5, 5.0, 11, corridor_m});
  for (int i = 0; i < 3; ++i)
    DrawDoor(plan, 0.5 + (i + 0.5) * 3.5, 5.0, door_m, WallDirection::kHorizontal);
  return plan;
}

// The free width of a corridor drawn `between_walls_m` between wall centres.
double FreeWidth(const FloorPlan& plan, double between_walls_m) {
  return between_walls_m - plan.wall_thickness_px() * plan.resolution_m();
}

proto::RoomWidthEstimate Estimate(const FloorPlan& plan, bool above_doors = false) {
  const proto::CleanedMap map = CleanedMapFromImage(plan.image());
  const AreaStages stages = RunAreaStages(map);
  return EstimateRoomWidth(stages.topology, 0.05, map.robot_width_m(), /*fallback_m=*/1.25,
                           above_doors);
}

TEST(WidthEstimateTest, DoorOf90CmIsFoundWithin10Cm) {
  const FloorPlan plan = RoomsAlongACorridor(0.9, 2.0);
  const proto::RoomWidthEstimate estimate = Estimate(plan);
  EXPECT_TRUE(estimate.automatic());
  EXPECT_NEAR(estimate.widest_door_m(), 0.9, 0.1);
  ASSERT_EQ(estimate.doors_size(), 3);
  for (const proto::DetectedWidth& door : estimate.doors()) {
    EXPECT_NEAR(door.width_m(), 0.9, 0.1);
    // On the corridor's upper wall (y = 5 m), at one of the three doors.
    EXPECT_NEAR(door.position().y() * 0.05, 5.0, 0.3);
    const double x = door.position().x() * 0.05;
    EXPECT_NEAR(std::fmod(x - 0.5, 3.5), 1.75, 0.3) << x;
  }
  // Door narrower than the corridor: W = door + 0.1 m.
  EXPECT_NEAR(estimate.narrowest_corridor_m(), FreeWidth(plan, 2.0), 0.1);
  EXPECT_NEAR(estimate.room_width_m(), estimate.widest_door_m() + 0.1, 1e-9);
}

class DoorWidthTest : public ::testing::TestWithParam<double> {};

TEST_P(DoorWidthTest, EstimateIsWithin10Cm) {
  const double door = GetParam();
  const proto::RoomWidthEstimate estimate = Estimate(RoomsAlongACorridor(door, 2.5));
  EXPECT_NEAR(estimate.widest_door_m(), door, 0.1);
  EXPECT_NEAR(estimate.room_width_m(), door + 0.1, 0.1);
}

INSTANTIATE_TEST_SUITE_P(Doors, DoorWidthTest, ::testing::Values(0.8, 0.9, 1.0, 1.2));

class CorridorWidthTest : public ::testing::TestWithParam<double> {};

TEST_P(CorridorWidthTest, NarrowestCorridorIsItsFreeWidth) {
  const double corridor = GetParam();
  const FloorPlan plan = RoomsAlongACorridor(0.8, corridor);
  const proto::RoomWidthEstimate estimate = Estimate(plan);
  EXPECT_NEAR(estimate.narrowest_corridor_m(), FreeWidth(plan, corridor), 0.1);
  ASSERT_GT(estimate.corridors_size(), 0);
  for (const proto::DetectedWidth& found : estimate.corridors()) {
    EXPECT_GE(found.length_m(), kCorridorMinLengthM);
  }
}

INSTANTIATE_TEST_SUITE_P(Corridors, CorridorWidthTest, ::testing::Values(1.4, 1.8, 2.6));

TEST(WidthEstimateTest, DoorWiderThanTheCorridorFollowsTheRuleChosen) {
  // Two 5 m rooms joined by a 1.5 m door, both opening through 0.8 m doors
  // onto a 16 m corridor with about 1.05 m free.
  FloorPlan plan(17, 7.2);
  DrawRoom(plan, {0.5, 0.5, 5, 5});
  DrawRoom(plan, {5.5, 0.5, 5, 5});
  DrawRoom(plan, {0.5, 5.5, 16, 1.2});
  DrawDoor(plan, 5.5, 3, 1.5, WallDirection::kVertical);
  DrawDoor(plan, 3, 5.5, 0.8, WallDirection::kHorizontal);
  DrawDoor(plan, 8, 5.5, 0.8, WallDirection::kHorizontal);
  const proto::RoomWidthEstimate paper = Estimate(plan);
  EXPECT_EQ(paper.doors_size(), 3);
  EXPECT_NEAR(paper.widest_door_m(), 1.5, 0.1);
  EXPECT_NEAR(paper.narrowest_corridor_m(), FreeWidth(plan, 1.2), 0.1);
  // The paper's rule: corridor - 0.1 m.
  EXPECT_NEAR(paper.room_width_m(), paper.narrowest_corridor_m() - 0.1, 1e-9);
  // cut pass WIDTH_ABOVE_DOORS: door + 0.1 m.
  const proto::RoomWidthEstimate above = Estimate(plan, /*above_doors=*/true);
  EXPECT_NEAR(above.room_width_m(), above.widest_door_m() + 0.1, 1e-9);
}

TEST(WidthEstimateTest, DoorAsWideAsTheOpeningOfANarrowerCorridorIsNoConstriction) {
  // Seen from a corridor narrower than the door, the door does not narrow
  // anything: the width only grows into the room. Such a door is not found.
  const proto::RoomWidthEstimate estimate = Estimate(RoomsAlongACorridor(1.5, 1.2));
  EXPECT_EQ(estimate.doors_size(), 0);
}

TEST(WidthEstimateTest, OneRoomWithoutDoorsOrCorridorsFallsBack) {
  FloorPlan plan(6, 5);
  DrawRoom(plan, {0.5, 0.5, 5, 4});
  const proto::RoomWidthEstimate estimate = Estimate(plan);
  EXPECT_EQ(estimate.doors_size(), 0);
  EXPECT_EQ(estimate.widest_door_m(), 0);
  EXPECT_EQ(estimate.room_width_m(), 1.25);
}

TEST(WidthEstimateTest, CutGraphStoresTheEstimateAndUsesIt) {
  const proto::CleanedMap map = CleanedMapFromImage(RoomsAlongACorridor(0.9, 2.0).image());
  proto::PipelineOptions options;
  options.mutable_cut()->set_room_width_m(0);  // estimated (the default)
  const AreaStages stages = RunAreaStages(map, options);
  const proto::RoomWidthEstimate& stored = stages.cut.room_width();
  EXPECT_TRUE(stored.automatic());
  EXPECT_NEAR(stored.room_width_m(), 0.9 + kPaperWidthMarginM, 0.1);
  EXPECT_EQ(stored.doors_size(), 3);
  // Three rooms and a corridor, kept apart at the doors.
  EXPECT_EQ(stages.areas.areas_size(), 4);

  options.mutable_cut()->set_room_width_m(1.3);
  const AreaStages fixed = RunAreaStages(map, options);
  EXPECT_FALSE(fixed.cut.room_width().automatic());
  EXPECT_EQ(fixed.cut.room_width().room_width_m(), 1.3);
  EXPECT_EQ(fixed.cut.room_width().doors_size(), 0);
}

TEST(WidthEstimateTest, CorridorWithoutDoorsBecomesOneRoomUnderAuto) {
  // An L-shaped corridor, 1.0 m free: no doors, so W = corridor - 0.1 m and
  // the corridor holds the disk: one room, one area.
  FloorPlan plan(7.5, 7.5);
  floorplan::DrawRegion(plan, {{0.5, 0.5, 1.15, 6.5}, {0.5, 5.85, 6.5, 1.15}});
  const proto::CleanedMap map = CleanedMapFromImage(plan.image());
  const AreaStages stages = RunAreaStages(map);  // defaults: auto
  EXPECT_EQ(stages.cut.room_width().doors_size(), 0);
  EXPECT_NEAR(stages.cut.room_width().narrowest_corridor_m(), 1.0, 0.1);
  EXPECT_NEAR(stages.cut.room_width().room_width_m(), 0.9, 0.1);
  EXPECT_EQ(stages.cut.room_shapes_size(), 1);
  EXPECT_EQ(stages.areas.areas_size(), 1);
}

}  // namespace
}  // namespace areagraph::testing
