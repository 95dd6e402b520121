// merge's JOIN_SPLIT_CORRIDORS through the whole pipeline: a corridor 2.05 m
// wide narrows to 1.7 m between two short wall stubs, W is 1.9 m (as an
// automatic W near the corridor's width comes out), the room disk cannot pass
// the narrowing and the corridor falls into two room-shaped pieces; they are
// one corridor again. A room behind a door in line with the corridor stays a
// room.
#include <gtest/gtest.h>

#include "tests/support/area_test_support.h"
#include "tests/support/merge_pass_cases.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using floorplan::RectM;
using floorplan::WallDirection;

// A corridor 30 x 2.2 m (2.05 m between its walls) under a row of offices
// 4 m deep (doors 0.9 m).
constexpr RectM kCorridor{0.5, 4.5, 30, 2.2};
constexpr double kCorridorMiddleY = kCorridor.y + kCorridor.height / 2;

proto::PipelineOptions FixedW(bool join_split_corridors) {
  proto::PipelineOptions options;
  options.mutable_cut()->set_room_width_m(1.9);
  if (!join_split_corridors) {
    options.mutable_merge()->add_skip_passes(proto::MergeOptions::JOIN_SPLIT_CORRIDORS);
  }
  return options;
}

// The corridor of CorridorWithStubs (tests/support/merge_pass_cases.h), whose
// stubs narrow it at x = 15.5 m.
floorplan::FloorPlan SplitCorridor() { return CorridorWithStubs(); }

struct Result {
  int left = -1, right = -1, office = -1;
};

Result RunOn(const floorplan::FloorPlan& plan, const proto::PipelineOptions& options) {
  const proto::CleanedMap map = CleanDrawnMap(plan.image());
  const AreaStages stages = RunAreaStages(map, options);
  ExpectAreaGraphInvariants(stages, map, 0.9);
  return {AreaAt(stages.areas, 5, kCorridorMiddleY), AreaAt(stages.areas, 26, kCorridorMiddleY),
          AreaAt(stages.areas, 13, 2.5)};
}

TEST(SplitCorridorTest, WithoutTheRuleTheNarrowingSplitsTheCorridor) {
  const Result result = RunOn(SplitCorridor(), FixedW(false));
  ASSERT_NE(result.left, -1);
  ASSERT_NE(result.right, -1);
  EXPECT_NE(result.left, result.right);
}

TEST(SplitCorridorTest, PiecesOfOneCorridorJoin) {
  const Result result = RunOn(SplitCorridor(), FixedW(true));
  ASSERT_NE(result.left, -1);
  EXPECT_EQ(result.left, result.right);
  // The offices stay rooms of their own behind their doors.
  ASSERT_NE(result.office, -1);
  EXPECT_NE(result.office, result.left);
}

TEST(SplitCorridorTest, ARoomBehindADoorInLineStaysApart) {
  // The corridor ends at x = 30.5 m in a wall with a 1.2 m door, centred on
  // the corridor, into a room as wide as the corridor and 6 m long beyond it:
  // together they are as long and narrow as a corridor, but the door narrows.
  floorplan::FloorPlan plan(38, 7.5);
  DrawOffices(plan, 30, 5, kCorridor.y);
  floorplan::DrawRoom(plan, kCorridor);
  floorplan::DrawRoom(plan, {30.5, kCorridor.y, 6, kCorridor.height});
  floorplan::DrawDoor(plan, 30.5, kCorridorMiddleY, 1.2, WallDirection::kVertical);
  const proto::CleanedMap map = CleanDrawnMap(plan.image());
  const AreaStages stages = RunAreaStages(map, FixedW(true));
  ExpectAreaGraphInvariants(stages, map, 0.9);
  const int corridor = AreaAt(stages.areas, 20, kCorridorMiddleY);
  const int room = AreaAt(stages.areas, 33.5, kCorridorMiddleY);
  ASSERT_NE(corridor, -1);
  ASSERT_NE(room, -1);
  EXPECT_NE(corridor, room);
}

}  // namespace
}  // namespace areagraph::testing
