// A free-standing block (a partition with furniture drawn around it, like
// the one in bormann/ lab_ipa_furnitures) in a room, with a cabinet against
// the top wall in its line (cut pass WALL_PIECES_NEED_BOTH_ENDS). The cabinet
// continues the block end-on past a 0.6 m gap, but the block's other end is
// 2 m from the bottom wall, more than a door: it stands in the room, it is
// not a piece of wall between two doors. With W = 2.6 m (wider than that
// gap, as lab_ipa's estimate) the room disk fills the room as one room with
// the option on, and stops at the block with it off: two rooms, one on each
// side. (Here merge joins the two again at the 2 m gap; in lab_ipa it could
// not, the gap being a door the cut closed.)
#include <gtest/gtest.h>

#include "tests/support/area_test_support.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

// Points left and right of the block, halfway down it.
constexpr double kLeftX = 1.5, kRightX = 5.5, kMiddleY = 2.9;

// The room 7 x 6 m, the block 1 x 2.4 m 0.6 m below a cabinet 0.5 x 1 m
// that stands against the top wall, and four narrow rooms beside the room
// (their walls set the map's typical wall thickness).
floorplan::FloorPlan RoomWithPartition() {
  floorplan::FloorPlan plan(12.2, 6.2);
  floorplan::DrawRoom(plan, {0.1, 0.1, 7, 6});
  for (int k = 0; k < 4; ++k) floorplan::DrawRoom(plan, {7.1 + 1.25 * k, 0.1, 1.25, 6});
  floorplan::DrawFurniture(plan, {3.15, 0.1, 0.5, 1.0});
  floorplan::DrawFurniture(plan, {2.9, 1.7, 1.0, 2.4});
  return plan;
}

AreaStages Stages(bool both_ends) {
  proto::PipelineOptions options;
  options.mutable_cut()->set_room_width_m(2.6);
  if (!both_ends) {
    options.mutable_cut()->add_skip_passes(proto::CutOptions::WALL_PIECES_NEED_BOTH_ENDS);
  }
  const proto::CleanedMap map = CleanDrawnMap(RoomWithPartition().image());
  const AreaStages stages = RunAreaStages(map, options);
  ExpectAreaGraphInvariants(stages, map, 0.9);
  return stages;
}

TEST(PartitionCabinetTest, TheRoomIsOneRoomAndOneArea) {
  const AreaStages stages = Stages(true);
  EXPECT_EQ(stages.cut.room_shapes_size(), 1);
  const int left = AreaAt(stages.areas, kLeftX, kMiddleY);
  ASSERT_NE(left, -1);
  EXPECT_EQ(AreaAt(stages.areas, kRightX, kMiddleY), left);
}

TEST(PartitionCabinetTest, WithOneContinuedEndTheBlockIsAWallAndSplitsTheRoom) {
  EXPECT_EQ(Stages(false).cut.room_shapes_size(), 2);
}

}  // namespace
}  // namespace areagraph::testing
