// Merge's corridor rules through the whole pipeline, each on a drawn
// corridor that a fixed W splits: a narrowing with a flat wall on one side
// and a corridor that W cuts into three short pieces (JOIN_SPLIT_CORRIDORS),
// and a dead-end branch narrower than W (JOIN_CORRIDOR_STEMS, which keeps it
// apart when skipped). Doors stay doors.
#include <gtest/gtest.h>

#include "tests/support/area_test_support.h"
#include "tests/support/merge_pass_cases.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using floorplan::RectM;
using floorplan::WallDirection;

// A corridor 2.2 m between wall centres (2.05 m free) at y = 4.5 m under a
// row of offices 4 m deep with 0.9 m doors (drawn after the corridor, so that
// its wall does not cover their doors).
constexpr double kCorridorY = 4.5;
constexpr double kCorridorHeight = 2.2;
constexpr double kCorridorMiddleY = kCorridorY + kCorridorHeight / 2;

proto::PipelineOptions FixedW(double w) { return FixedRoomWidth(w); }

proto::AreaGraph Areas(const floorplan::FloorPlan& plan, const proto::PipelineOptions& options) {
  const proto::CleanedMap map = CleanDrawnMap(plan.image());
  const AreaStages stages = RunAreaStages(map, options);
  ExpectAreaGraphInvariants(stages, map, 0.9);
  return stages.areas;
}

// A corridor 20 m long whose top wall has a cabinet 0.6 m deep and 1 m long
// against it at x = 11-12 m (beside an office's door): 1.45 m stay free
// beside it, against the flat bottom wall. W = 1.7 m fills the corridor but
// not the gap.
floorplan::FloorPlan CabinetCorridor() {
  floorplan::FloorPlan plan(21, 7.5);
  floorplan::DrawRoom(plan, {0.5, kCorridorY, 20, kCorridorHeight});
  DrawOffices(plan, 20, 5, kCorridorY);
  floorplan::DrawFurniture(plan, {11, kCorridorY, 1, 0.675});
  return plan;
}

TEST(OneSidedNarrowingTest, ACabinetAgainstOneWallDoesNotSplitTheCorridor) {
  const proto::AreaGraph areas = Areas(CabinetCorridor(), FixedW(1.7));
  const int left = AreaAt(areas, 4, kCorridorMiddleY), right = AreaAt(areas, 17, kCorridorMiddleY);
  ASSERT_NE(left, -1);
  EXPECT_EQ(left, right);
  const int office = AreaAt(areas, 8, 2.5);
  ASSERT_NE(office, -1);
  EXPECT_NE(office, left);
}

TEST(OneSidedNarrowingTest, ADoorAcrossTheCorridorStillDividesIt) {
  // A wall across the corridor at x = 10.5 m with a 1.45 m door in its
  // middle: the same width as beside the cabinet, but with two jambs.
  floorplan::FloorPlan plan(21, 7.5);
  floorplan::DrawRoom(plan, {0.5, kCorridorY, 10, kCorridorHeight});
  floorplan::DrawRoom(plan, {10.5, kCorridorY, 10, kCorridorHeight});
  DrawOffices(plan, 20, 5, kCorridorY);
  floorplan::DrawDoor(plan, 10.5, kCorridorMiddleY, 1.45, WallDirection::kVertical);
  const proto::AreaGraph areas = Areas(plan, FixedW(1.7));
  const int left = AreaAt(areas, 4, kCorridorMiddleY), right = AreaAt(areas, 17, kCorridorMiddleY);
  ASSERT_NE(left, -1);
  ASSERT_NE(right, -1);
  EXPECT_NE(left, right);
}

// A corridor 13.5 m long narrowed to 1.7 m by pairs of short wall stubs at
// x = 5 and 9.5 m: W = 1.9 m cuts it into three pieces of about 9 m2, no two
// of them together 6 squares of the corridor's width (25 m2), all three so.
floorplan::FloorPlan ThreePieceCorridor() {
  floorplan::FloorPlan plan(15, 7.5);
  floorplan::DrawRoom(plan, {0.5, kCorridorY, 13.5, kCorridorHeight});
  DrawOffices(plan, 13.5, 4.5, kCorridorY);
  for (const double x : {5.0, 9.5}) {
    floorplan::DrawFurniture(plan, {x - 0.15, kCorridorY, 0.3, 0.25});
    floorplan::DrawFurniture(plan, {x - 0.15, kCorridorY + kCorridorHeight - 0.25, 0.3, 0.25});
  }
  return plan;
}

TEST(SplitCorridorChainTest, ThreeShortPiecesOfOneCorridorJoin) {
  const proto::AreaGraph areas = Areas(ThreePieceCorridor(), FixedW(1.9));
  const int left = AreaAt(areas, 2.5, kCorridorMiddleY);
  ASSERT_NE(left, -1);
  EXPECT_EQ(AreaAt(areas, 7.25, kCorridorMiddleY), left);
  EXPECT_EQ(AreaAt(areas, 12, kCorridorMiddleY), left);
  const int office = AreaAt(areas, 7, 2.5);
  ASSERT_NE(office, -1);
  EXPECT_NE(office, left);
}

// CorridorWithStem (tests/support/merge_pass_cases.h) with W = 1.5 m: the
// branch and the closet get no room.
constexpr double kStemX = 7.0, kStemY = 9.5, kClosetX = 15.6, kClosetY = 9.0;

TEST(CorridorStemTest, WithoutTheRuleTheBranchStaysApart) {
  proto::PipelineOptions options = FixedW(1.5);
  options.mutable_merge()->add_skip_passes(proto::MergeOptions::JOIN_CORRIDOR_STEMS);
  const proto::AreaGraph areas = Areas(CorridorWithStem(), options);
  const int corridor = AreaAt(areas, 3, kCorridorMiddleY), stem = AreaAt(areas, kStemX, kStemY);
  ASSERT_NE(corridor, -1);
  ASSERT_NE(stem, -1);
  EXPECT_NE(corridor, stem);
}

TEST(CorridorStemTest, ADeadEndBranchIsPartOfItsCorridor) {
  const proto::AreaGraph areas = Areas(CorridorWithStem(), FixedW(1.5));
  const int corridor = AreaAt(areas, 3, kCorridorMiddleY);
  ASSERT_NE(corridor, -1);
  EXPECT_EQ(AreaAt(areas, kStemX, kStemY), corridor);
  // The closet behind its narrower door stays apart.
  const int closet = AreaAt(areas, kClosetX, kClosetY);
  ASSERT_NE(closet, -1);
  EXPECT_NE(closet, corridor);
}

}  // namespace
}  // namespace areagraph::testing
