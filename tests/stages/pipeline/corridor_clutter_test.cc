// merge.wall_furniture_islands and merge.join_corridor_clutter through the
// whole pipeline: a cabinet standing against a corridor's wall narrows the
// corridor below W, the room disk stops there, and the corridor stays one
// area (bormann/ office_h furnished, whose bins stand against the corridor's
// walls); a wall across the corridor with a door in it still divides it.
#include <gtest/gtest.h>

#include "tests/support/area_test_support.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using floorplan::RectM;
using floorplan::WallDirection;

// A corridor 44 x 2.6 m below a hall as long, 3 m deep, with a 1 m door
// between them at x = 5 m. W is fixed at 2.2 m: the room disk fills the
// corridor but not a gap of 1.7 m.
constexpr RectM kHall{0.5, 0.5, 44, 3};
constexpr RectM kCorridor{0.5, 3.5, 44, 2.6};
// A cabinet 1.2 m wide and 0.9 m deep against the corridor's top wall (the
// hall's, free behind it) in its middle: 1.7 m of the corridor are left.
// Against the map's outer wall, with unknown space behind it, a cabinet is
// part of a thick region that reaches the image border: no island.
constexpr RectM kCabinet{21.9, 3.5, 1.2, 0.9};

proto::PipelineOptions FixedW() {
  proto::PipelineOptions options;
  options.mutable_cut()->set_room_width_auto(false);
  options.mutable_cut()->set_room_width_m(2.2);
  return options;
}

// The areas left and right of the middle of the corridor.
std::pair<int, int> CorridorEnds(const floorplan::FloorPlan& plan,
                                 const proto::PipelineOptions& options) {
  const proto::CleanedMap map = CleanDrawnMap(plan.image());
  const AreaStages stages = RunAreaStages(map, options);
  ExpectAreaGraphInvariants(stages, map, 0.9);
  return {AreaAt(stages.areas, 10, 5.0), AreaAt(stages.areas, 35, 5.0)};
}

floorplan::FloorPlan CorridorWithCabinet() {
  floorplan::FloorPlan plan(45, 6.6);
  floorplan::DrawRoom(plan, kHall);
  floorplan::DrawRoom(plan, kCorridor);
  floorplan::DrawDoor(plan, 5, kCorridor.y, 1.0, WallDirection::kHorizontal);
  floorplan::DrawFurniture(plan, kCabinet);
  return plan;
}

TEST(CorridorClutterTest, CabinetAgainstTheWallDoesNotDivideTheCorridor) {
  const auto [left, right] = CorridorEnds(CorridorWithCabinet(), FixedW());
  ASSERT_NE(left, -1);
  EXPECT_EQ(left, right);
}

TEST(CorridorClutterTest, WithoutEitherRuleTheCabinetDividesTheCorridor) {
  for (const bool against_walls : {false, true}) {
    proto::PipelineOptions options = FixedW();
    options.mutable_merge()->set_wall_furniture_islands(against_walls);
    options.mutable_merge()->set_join_corridor_clutter(!against_walls);
    // Merge 13's one-sided narrowings join this cabinet's two halves too (it
    // stands against one wall); off, so that only merge 11's rules are tested.
    options.mutable_merge()->set_join_one_sided_narrowings(false);
    const auto [left, right] = CorridorEnds(CorridorWithCabinet(), options);
    ASSERT_NE(left, -1);
    ASSERT_NE(right, -1);
    EXPECT_NE(left, right) << "wall_furniture_islands " << against_walls;
  }
}

TEST(CorridorClutterTest, WallWithADoorAcrossTheCorridorStillDividesIt) {
  // A thin wall across the corridor at x = 22.5 m with a 1.4 m doorway.
  floorplan::FloorPlan plan(45, 6.6);
  floorplan::DrawRoom(plan, kHall);
  floorplan::DrawRoom(plan, {0.5, 3.5, 22, 2.6});
  floorplan::DrawRoom(plan, {22.5, 3.5, 22, 2.6});
  floorplan::DrawDoor(plan, 5, kCorridor.y, 1.0, WallDirection::kHorizontal);
  floorplan::DrawDoor(plan, 22.5, 4.8, 1.4, WallDirection::kVertical);
  const auto [left, right] = CorridorEnds(plan, FixedW());
  ASSERT_NE(left, -1);
  ASSERT_NE(right, -1);
  EXPECT_NE(left, right);
}

}  // namespace
}  // namespace areagraph::testing
