// Local door decisions (cut pass CLOSE_WALL_DOORS) through the whole pipeline: a
// door wider than the map's W still divides the room behind it from the
// corridor, while furniture keeps a room whole (furniture_rooms_test).
#include <gtest/gtest.h>

#include "tests/support/area_test_support.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using floorplan::WallDirection;

// Ten 4 x 4 m offices on both sides of a corridor, each opening into it
// through a 0.9 m door, except the third office on top, whose door is wider.
struct CorridorPlan {
  double plan_height_m = 0;
  double corridor_height_m = 0;  // between wall centres
  double wide_door_m = 0;
};
constexpr double kWideDoorX = 10.5, kCorridorY = 4.5;

// The corridor is 2 m between wall centres and the wide door 1.3 m: W (above
// the 90th percentile of the doors, the 0.9 m ones) is narrower than it.
constexpr CorridorPlan kWideDoorPlan{11, 2, 1.3};

// The corridor is 1.4 m between wall centres (1.3 m free) and the wide door
// 1.8 m: wider than the corridor, so the space does not widen on the
// corridor's side of it and the width estimate finds no door there
// (cut pass CLOSE_WALL_GAPS must close it).
constexpr CorridorPlan kNarrowCorridorPlan{10, 1.4, 1.8};

floorplan::FloorPlan OfficesAlongACorridor(const CorridorPlan& shape) {
  floorplan::FloorPlan plan(21, shape.plan_height_m);
  const double below = kCorridorY + shape.corridor_height_m;
  for (int i = 0; i < 5; ++i) {
    floorplan::DrawRoom(plan, {0.5 + 4 * i, 0.5, 4, 4});
    floorplan::DrawRoom(plan, {0.5 + 4 * i, below, 4, 4});
  }
  floorplan::DrawRoom(plan, {0.5, kCorridorY, 20, shape.corridor_height_m});
  for (int i = 0; i < 5; ++i) {
    const double x = 2.5 + 4 * i;
    floorplan::DrawDoor(plan, x, kCorridorY, x == kWideDoorX ? shape.wide_door_m : 0.9,
                        WallDirection::kHorizontal);
    floorplan::DrawDoor(plan, x, below, 0.9, WallDirection::kHorizontal);
  }
  return plan;
}

struct WideDoorAreas {
  double room_width_m = 0;
  int office = -1;
  int corridor = -1;
  proto::AreaKind office_kind = proto::AREA_CORRIDOR;
  proto::AreaKind corridor_kind = proto::AREA_ROOM;
};

WideDoorAreas RunOffices(const CorridorPlan& shape, const proto::PipelineOptions& options) {
  const proto::CleanedMap map = CleanDrawnMap(OfficesAlongACorridor(shape).image());
  const AreaStages stages = RunAreaStages(map, options);
  WideDoorAreas found;
  found.room_width_m = stages.cut.room_width().room_width_m();
  found.office = AreaAt(stages.areas, kWideDoorX, 2.5);
  found.corridor = AreaAt(stages.areas, kWideDoorX, kCorridorY + shape.corridor_height_m / 2);
  if (found.office >= 0) found.office_kind = stages.areas.areas(found.office).kind();
  if (found.corridor >= 0) found.corridor_kind = stages.areas.areas(found.corridor).kind();
  return found;
}

TEST(LocalDoorsTest, DoorWiderThanWStillDividesOfficeFromCorridor) {
  const WideDoorAreas found = RunOffices(kWideDoorPlan, {});
  EXPECT_LT(found.room_width_m, kWideDoorPlan.wide_door_m);
  ASSERT_NE(found.office, -1);
  ASSERT_NE(found.corridor, -1);
  EXPECT_NE(found.office, found.corridor);
}

TEST(LocalDoorsTest, WithOneGlobalWTheOfficeLeaksIntoTheCorridor) {
  // The paper's single W: the room disk passes the wide door.
  proto::PipelineOptions options;
  options.mutable_cut()->add_skip_passes(proto::CutOptions::CLOSE_WALL_DOORS);
  options.mutable_cut()->add_skip_passes(proto::CutOptions::CLOSE_WALL_GAPS);
  const WideDoorAreas found = RunOffices(kWideDoorPlan, options);
  EXPECT_LT(found.room_width_m, kWideDoorPlan.wide_door_m);
  EXPECT_EQ(found.office, found.corridor);
}

// The drawn walls are thin, so the wall gap rule closes the wide door too;
// with wall gaps only up to 1 m closed, CLOSE_WALL_DOORS alone divides.
proto::PipelineOptions NarrowWallGaps() {
  proto::PipelineOptions options;
  options.mutable_cut()->mutable_wall_gaps()->set_max_width_m(1.0);
  return options;
}

TEST(LocalDoorsTest, ClosingWallDoorsDividesOfficeFromCorridor) {
  const WideDoorAreas found = RunOffices(kWideDoorPlan, NarrowWallGaps());
  ASSERT_NE(found.office, -1);
  EXPECT_NE(found.office, found.corridor);
}

TEST(LocalDoorsTest, WithoutClosingWallDoorsTheOfficeLeaksIntoTheCorridor) {
  proto::PipelineOptions options = NarrowWallGaps();
  options.mutable_cut()->add_skip_passes(proto::CutOptions::CLOSE_WALL_DOORS);
  const WideDoorAreas found = RunOffices(kWideDoorPlan, options);
  EXPECT_EQ(found.office, found.corridor);
}

TEST(LocalDoorsTest, DoorWiderThanItsCorridorDividesOfficeFromCorridor) {
  const WideDoorAreas found = RunOffices(kNarrowCorridorPlan, {});
  EXPECT_LT(found.room_width_m, kNarrowCorridorPlan.corridor_height_m);
  ASSERT_NE(found.office, -1);
  ASSERT_NE(found.corridor, -1);
  EXPECT_NE(found.office, found.corridor);
}

TEST(LocalDoorsTest, WithoutWallGapsTheDoorWiderThanItsCorridorStaysOpen) {
  proto::PipelineOptions options;
  options.mutable_cut()->add_skip_passes(proto::CutOptions::CLOSE_WALL_GAPS);
  const WideDoorAreas found = RunOffices(kNarrowCorridorPlan, options);
  EXPECT_EQ(found.office, found.corridor);
}

TEST(LocalDoorsTest, CorridorWiderThanWIsLabelledACorridor) {
  // The room disk (W about 1 m) fits in the 1.85 m corridor, but the
  // corridor is ten times as long as it is wide (SetAreaKinds).
  const WideDoorAreas found = RunOffices(kWideDoorPlan, {});
  ASSERT_NE(found.office, -1);
  ASSERT_NE(found.corridor, -1);
  EXPECT_EQ(found.corridor_kind, proto::AREA_CORRIDOR);
  EXPECT_EQ(found.office_kind, proto::AREA_ROOM);
}

}  // namespace
}  // namespace areagraph::testing
