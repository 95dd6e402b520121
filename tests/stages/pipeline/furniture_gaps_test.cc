// merge's JOIN_FURNITURE_GAPS through the whole pipeline: a cabinet standing
// free across a room, too close to the walls for the room disk to pass, no
// longer splits the room; a piece of wall between two doors still does. With
// its filled outline, neither does a cabinet drawn as a closed
// outline (lab_d's desks).
#include <gtest/gtest.h>

#include "tests/support/area_test_support.h"
#include "tests/support/merge_pass_cases.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using floorplan::RectM;

// RoomWithDivider (tests/support/merge_pass_cases.h) with kCabinetAcrossRoom:
// 0.7 m to the walls above and below it, narrower than W.
constexpr RectM kCabinet = kCabinetAcrossRoom;
// A wall 0.15 m thick in the same place: a wall with a doorway at each end.
constexpr RectM kWallPiece{3.43, 1.8, 0.15, 2.45};

// kCabinet drawn as a closed outline 2 cells thick, free inside.
floorplan::FloorPlan RoomWithOutlinedCabinet() {
  floorplan::FloorPlan plan = RoomWithDivider(kCabinet);
  const cv::Rect cabinet(plan.ToPixels(kCabinet.x), plan.ToPixels(kCabinet.y),
                         plan.ToPixels(kCabinet.x + kCabinet.width) - plan.ToPixels(kCabinet.x),
                         plan.ToPixels(kCabinet.y + kCabinet.height) - plan.ToPixels(kCabinet.y));
  plan.image()(cabinet - cv::Point(-2, -2) - cv::Size(4, 4)).setTo(floorplan::kFreeGrey);
  return plan;
}

struct Sides {
  int left = -1, right = -1, corridor = -1;
};

Sides AreasOf(const floorplan::FloorPlan& plan, const proto::PipelineOptions& options) {
  const proto::CleanedMap map = CleanDrawnMap(plan.image());
  const AreaStages stages = RunAreaStages(map, options);
  ExpectAreaGraphInvariants(stages, map, 0.9);
  return {AreaAt(stages.areas, 2, 3), AreaAt(stages.areas, 5, 3), AreaAt(stages.areas, 5, 5.9)};
}

// Both sides of the divider are one area, and not the corridor's.
void ExpectOneRoomBesideTheCorridor(const Sides& sides) {
  ASSERT_NE(sides.left, -1);
  ASSERT_NE(sides.corridor, -1);
  EXPECT_EQ(sides.left, sides.right);
  EXPECT_NE(sides.left, sides.corridor);
}

// The divider splits the room into two areas.
void ExpectRoomSplit(const Sides& sides) {
  ASSERT_NE(sides.left, -1);
  ASSERT_NE(sides.right, -1);
  EXPECT_NE(sides.left, sides.right);
}

TEST(FurnitureGapsTest, CabinetAcrossARoomDoesNotSplitIt) {
  const Sides sides = AreasOf(RoomWithDivider(kCabinet), {});
  ExpectOneRoomBesideTheCorridor(sides);
}

TEST(FurnitureGapsTest, WithoutTheRuleTheCabinetSplitsTheRoom) {
  proto::PipelineOptions options;
  options.mutable_merge()->add_skip_passes(proto::MergeOptions::JOIN_FURNITURE_GAPS);
  const Sides sides = AreasOf(RoomWithDivider(kCabinet), options);
  ExpectRoomSplit(sides);
}

TEST(FurnitureGapsTest, WallPieceBetweenTwoDoorwaysStillDividesTheRoom) {
  const Sides sides = AreasOf(RoomWithDivider(kWallPiece), {});
  ExpectRoomSplit(sides);
}

TEST(FurnitureGapsTest, CabinetDrawnAsOutlineDoesNotSplitTheRoom) {
  const floorplan::FloorPlan plan = RoomWithOutlinedCabinet();
  // The outline is hollow: its inside is free.
  const cv::Rect cabinet(plan.ToPixels(kCabinet.x), plan.ToPixels(kCabinet.y), 1, 1);
  ASSERT_EQ(plan.image().at<uint8_t>(cabinet.y + 10, cabinet.x + 5), floorplan::kFreeGrey);
  ASSERT_EQ(plan.image().at<uint8_t>(cabinet.y + 10, cabinet.x), floorplan::kWallGrey);
  const Sides sides = AreasOf(plan, {});
  ExpectOneRoomBesideTheCorridor(sides);
}

}  // namespace
}  // namespace areagraph::testing
