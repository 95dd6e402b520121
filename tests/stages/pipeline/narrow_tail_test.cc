// A hall with a narrow tail (cut pass CUT_NARROW_TAILS, and merge's
// JOIN_CORRIDOR_STEMS joins stems only into corridors): a corridor 1.45 m wide and 7 m long
// running on from the side of a hall 6 m wide, open across its whole width,
// like the side corridors of areagraph/ Freiburg101_scan. W (about 1 m, from
// the office's door) is narrower than the tail, so the room disk fills hall
// and tail as one room; the tail is its own area with the option on and
// part of the hall with it off.
#include <gtest/gtest.h>

#include "tests/support/area_test_support.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using floorplan::RectM;
using floorplan::WallDirection;

constexpr double kHallX = 3, kHallY = 7.5, kTailX = 30.7, kTailY = 14;

// The hall 40 x 6 m at y = 4.5-10.5 m (long enough to count as a corridor
// for stem joining), the tail 1.6 m between wall centres down from its
// bottom wall at x = 29.9-31.5 m, and an office above the hall
// behind a 0.9 m door.
floorplan::FloorPlan HallWithTail() {
  floorplan::FloorPlan plan(41, 18.5);
  floorplan::DrawRoom(plan, {6, 0.5, 5, 4});
  floorplan::DrawRegion(plan, {{0.5, 4.5, 40, 6}, {29.9, 10, 1.6, 7.5}});
  floorplan::DrawDoor(plan, 8.5, 4.5, 0.9, WallDirection::kHorizontal);
  return plan;
}

proto::AreaGraph Areas(const proto::PipelineOptions& options) {
  const proto::CleanedMap map = CleanDrawnMap(HallWithTail().image());
  const AreaStages stages = RunAreaStages(map, options);
  ExpectAreaGraphInvariants(stages, map, 0.9);
  return stages.areas;
}

TEST(NarrowTailTest, TheTailIsItsOwnArea) {
  const proto::AreaGraph areas = Areas({});
  const int hall = AreaAt(areas, kHallX, kHallY), tail = AreaAt(areas, kTailX, kTailY);
  ASSERT_NE(hall, -1);
  ASSERT_NE(tail, -1);
  EXPECT_NE(hall, tail);
  // The cut lies at the tail's mouth: the hall's cells beside it stay the hall's.
  EXPECT_EQ(AreaAt(areas, kTailX, 10.0), hall);
  EXPECT_EQ(AreaAt(areas, kTailX, 11.5), tail);
}

TEST(NarrowTailTest, WithoutTheCutTheTailIsPartOfTheHall) {
  proto::PipelineOptions options;
  options.mutable_cut()->add_skip_passes(proto::CutOptions::CUT_NARROW_TAILS);
  const proto::AreaGraph areas = Areas(options);
  const int hall = AreaAt(areas, kHallX, kHallY);
  ASSERT_NE(hall, -1);
  EXPECT_EQ(AreaAt(areas, kTailX, kTailY), hall);
}

}  // namespace
}  // namespace areagraph::testing
