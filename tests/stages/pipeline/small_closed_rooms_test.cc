// A closet of about 1.4 m2 behind a 0.8 m door in a 6 x 5 m room (as the
// small rooms of areagraph/ lab_d_scan_furnitures and freiburg_building101):
// the cut closes the door, but the closet's piece of the edge is shorter
// than W, so the cut joined it to the room's piece (cut pass KEEP_CLOSED_ROOM_TIPS
// keeps it), and ag-merge folded the closet, smaller than merge.min_area_m2,
// into the room (merge's KEEP_SMALL_CLOSED_ROOMS keeps it).
#include <gtest/gtest.h>

#include "tests/support/area_test_support.h"
#include "tests/support/merge_pass_cases.h"
#include "tools/example_maps/benchmark_floor.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

// RoomAndCloset (tests/support/merge_pass_cases.h).

struct Result {
  int room = -1, closet = -1;
};

Result RunOn(const floorplan::FloorPlan& plan, const proto::PipelineOptions& options) {
  const proto::CleanedMap map = CleanDrawnMap(plan.image(), options.clean());
  const AreaStages stages = RunAreaStages(map, options);
  ExpectAreaGraphInvariants(stages, map, 0.9);
  return {AreaAt(stages.areas, 3.5, 3), AreaAt(stages.areas, 7.1, 1.25)};
}

// Generated tuning floor_16 (0.042 m/px): a room of about 3 x 3.4 m whose top
// left corner is a pocket of about 0.9 x 1.3 m between a cabinet against the
// left wall and one against the top wall. The cut closes the 0.56 m gap
// between the cabinets' corners as a door. Areas at the pocket and at the
// room's middle.
std::pair<int, int> PocketAndRoomOfFloor16(const proto::PipelineOptions& options) {
  const floorplan::BenchmarkFloor floor = floorplan::RandomBenchmarkFloor(16);
  const double res = floor.plan.resolution_m();
  const proto::CleanedMap map = CleanDrawnMap(floor.plan.image(), options.clean(), res);
  const AreaStages stages = RunAreaStages(map, options);
  ExpectAreaGraphInvariants(stages, map, 0.9);
  return {AreaAt(stages.areas, 6.6, 1.6, res), AreaAt(stages.areas, 7.85, 3.15, res)};
}

TEST(SmallClosedRoomsTest, AClosetBehindAClosedDoorIsAnAreaOfItsOwn) {
  const Result result = RunOn(RoomAndCloset(), {});
  ASSERT_NE(result.room, -1);
  ASSERT_NE(result.closet, -1);
  EXPECT_NE(result.room, result.closet);
}

TEST(SmallClosedRoomsTest, WithoutKeepSmallClosedRoomsTheClosetFolds) {
  proto::PipelineOptions options;
  options.mutable_merge()->add_skip_passes(proto::MergeOptions::KEEP_SMALL_CLOSED_ROOMS);
  const Result result = RunOn(RoomAndCloset(), options);
  ASSERT_NE(result.room, -1);
  EXPECT_EQ(result.room, result.closet);
}

TEST(SmallClosedRoomsTest, WithoutKeepClosedRoomTipsTheClosetJoinsTheRoom) {
  proto::PipelineOptions options;
  options.mutable_cut()->add_skip_passes(proto::CutOptions::KEEP_CLOSED_ROOM_TIPS);
  const Result result = RunOn(RoomAndCloset(), options);
  ASSERT_NE(result.room, -1);
  EXPECT_EQ(result.room, result.closet);
}

// The walls-seen condition: a closet whose far wall is unknown space may be
// the edge of what the scan saw, and it folds.
TEST(SmallClosedRoomsTest, AClosetBesideUnknownSpaceFolds) {
  const Result result = RunOn(RoomAndCloset(/*far_wall_unknown=*/true), {});
  ASSERT_NE(result.room, -1);
  EXPECT_EQ(result.room, result.closet);
}

// merge.small_closed_rooms.pocket_jamb_m: the pocket's "door" runs between two
// cabinet corners, thick obstacles beyond both jambs, so the pocket stays in
// its room (the closet above, whose door lies in a wall, stays a room).
TEST(SmallClosedRoomsTest, APocketBetweenCabinetsStaysInTheRoom) {
  const auto [pocket, room] = PocketAndRoomOfFloor16({});
  ASSERT_NE(room, -1);
  EXPECT_EQ(pocket, room);
}

TEST(SmallClosedRoomsTest, WithoutThePocketTestThePocketIsAnArea) {
  proto::PipelineOptions options;
  options.mutable_merge()->mutable_small_closed_rooms()->set_pocket_jamb_m(0);
  const auto [pocket, room] = PocketAndRoomOfFloor16(options);
  ASSERT_NE(room, -1);
  ASSERT_NE(pocket, -1);
  EXPECT_NE(pocket, room);
}

}  // namespace
}  // namespace areagraph::testing
