// prune.keep_groups_above_m through the whole pipeline: a large room whose
// only opening is a gap narrower than twice prune.min_clearance_m (a cluttered
// doorway, areagraph/ lab_b) has a graph of its own, cut off from the rest of
// its free-space part; the paper keeps only the part's longest graph, and
// the areas' growth does not pass the gap either (merge pass GROWTH_STOPS_AT_NARROW_GAPS), so
// the room got no area at all.
#include <gtest/gtest.h>

#include "tests/support/area_test_support.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using floorplan::WallDirection;

// A hall 20 x 8 m and, right of it, a room 12 x 8 m behind a 0.15 m gap in
// the wall between them (x = 20.5 m). The hall's graph is the longer one.
proto::AreaGraph HallAndRoom(const proto::PipelineOptions& options) {
  floorplan::FloorPlan plan(33, 9);
  floorplan::DrawRoom(plan, {0.5, 0.5, 20, 8});
  floorplan::DrawRoom(plan, {20.5, 0.5, 12, 8});
  floorplan::DrawDoor(plan, 20.5, 4.5, 0.15, WallDirection::kVertical);
  const proto::CleanedMap map = CleanDrawnMap(plan.image());
  const AreaStages stages = RunAreaStages(map, options);
  ExpectAreaGraphInvariants(stages, map, 0.4);
  return stages.areas;
}

TEST(RoomBehindNarrowGapTest, LongGraphBehindTheGapGetsAreas) {
  const proto::AreaGraph areas = HallAndRoom({});
  const int hall = AreaAt(areas, 10, 4.5);
  const int room = AreaAt(areas, 26.5, 4.5);
  ASSERT_NE(hall, -1);
  ASSERT_NE(room, -1);
  EXPECT_NE(hall, room);
}

TEST(RoomBehindNarrowGapTest, WithoutTheRuleTheRoomIsLeftUnlabelled) {
  proto::PipelineOptions options;
  options.mutable_prune()->set_keep_groups_above_m(0);
  const proto::AreaGraph areas = HallAndRoom(options);
  EXPECT_NE(AreaAt(areas, 10, 4.5), -1);
  EXPECT_EQ(AreaAt(areas, 26.5, 4.5), -1);
}

}  // namespace
}  // namespace areagraph::testing
