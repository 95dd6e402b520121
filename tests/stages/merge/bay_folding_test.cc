// merge's FOLD_OPEN_BAYS: a bay that opens into a room over its whole width
// becomes part of the room; a closet behind a door stays an area of its own.
#include <gtest/gtest.h>

#include "tests/support/area_test_support.h"
#include "tests/support/merge_pass_cases.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using floorplan::DrawDoor;
using floorplan::DrawRoom;
using floorplan::FloorPlan;
using floorplan::WallDirection;

// A fixed W of 1.25 m (the bays below are narrower) and no folding of small
// areas, so that only bay folding can join them to the room.
proto::PipelineOptions BayOptions(bool fold_open_bays) {
  proto::PipelineOptions options;
  options.mutable_cut()->set_room_width_m(1.25);  // a fixed W (0, the default, estimates it)
  options.mutable_merge()->set_min_area_m2(0);
  if (!fold_open_bays) {
    options.mutable_merge()->add_skip_passes(proto::MergeOptions::FOLD_OPEN_BAYS);
  }
  return options;
}

// RoomWithOpenBay (tests/support/merge_pass_cases.h): the bay is narrower
// than W, outside the room shape, so the Topology Graph edge into it is
// room-less.

TEST(BayFoldingTest, OpenBayIsPartOfItsRoom) {
  const proto::CleanedMap map = CleanedMapFromImage(RoomWithOpenBay().image());
  const AreaStages stages = RunAreaStages(map, BayOptions(true));
  ExpectAreaGraphInvariants(stages, map);
  ASSERT_EQ(stages.areas.areas_size(), 1);
  EXPECT_EQ(stages.areas.passages_size(), 0);
  EXPECT_EQ(stages.areas.areas(0).kind(), proto::AREA_ROOM);
  EXPECT_EQ(AreaAt(stages.areas, 3.05, 6.2), AreaAt(stages.areas, 3.5, 2.5));
}

TEST(BayFoldingTest, WithoutTheOptionTheBayIsAnAreaOfItsOwn) {
  const proto::CleanedMap map = CleanedMapFromImage(RoomWithOpenBay().image());
  const AreaStages stages = RunAreaStages(map, BayOptions(false));
  ExpectAreaGraphInvariants(stages, map);
  ASSERT_EQ(stages.areas.areas_size(), 2);
  EXPECT_EQ(stages.areas.passages_size(), 1);
  const int bay = AreaAt(stages.areas, 3.05, 6.2), room = AreaAt(stages.areas, 3.5, 2.5);
  EXPECT_NE(bay, -1);
  EXPECT_NE(room, -1);
  EXPECT_NE(bay, room);
}

TEST(BayFoldingTest, ClosetBehindADoorStaysApart) {
  // The same bay, walled off from the room but for a 0.6 m door.
  FloorPlan plan(7, 7.5);
  DrawRoom(plan, {0.5, 0.5, 6, 4});
  DrawRoom(plan, {2.5, 4.5, 1.1, 2.5});
  DrawDoor(plan, 3.05, 4.5, 0.6, WallDirection::kHorizontal);
  const proto::CleanedMap map = CleanedMapFromImage(plan.image());
  const AreaStages stages = RunAreaStages(map, BayOptions(true));
  ExpectAreaGraphInvariants(stages, map);
  ASSERT_EQ(stages.areas.areas_size(), 2);
  EXPECT_NE(AreaAt(stages.areas, 3.05, 6.2), AreaAt(stages.areas, 3.5, 2.5));
}

}  // namespace
}  // namespace areagraph::testing
