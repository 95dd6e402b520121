// merge's JOIN_FURNITURE_GAPS through the whole pipeline: a cabinet standing
// free across a room, too close to the walls for the room disk to pass, no
// longer splits the room; a piece of wall between two doors still does. With
// its filled outline, neither does a cabinet drawn as a closed
// outline (lab_d's desks).
#include <gtest/gtest.h>

#include "tests/support/area_test_support.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using floorplan::RectM;
using floorplan::WallDirection;

// A 5 x 4 m room above a 1.8 m corridor, joined by a 0.9 m door at x = 2 m;
// a 4 x 4 m office beside it with its own 0.9 m door. Down the middle of the
// room (x = 3.5 m) stands `divider`, leaving 0.7 m to the walls above and
// below it: narrower than W (about 1 m, above the doors).
constexpr RectM kRoom{1, 1, 5, 4};
constexpr RectM kOffice{6, 1, 4, 4};
constexpr RectM kCorridor{1, 5, 9, 1.8};

floorplan::FloorPlan RoomWithDivider(const RectM& divider) {
  floorplan::FloorPlan plan(11, 7.8);
  floorplan::DrawRoom(plan, kRoom);
  floorplan::DrawRoom(plan, kOffice);
  floorplan::DrawRoom(plan, kCorridor);
  floorplan::DrawDoor(plan, 2, kCorridor.y, 0.9, WallDirection::kHorizontal);
  floorplan::DrawDoor(plan, 8, kCorridor.y, 0.9, WallDirection::kHorizontal);
  floorplan::DrawFurniture(plan, divider);
  return plan;
}

// A cabinet 0.6 m deep and 2.45 m long: too long and thin for ag-cut's
// furniture islands (cut.islands.max_length_m; islands are at most 3 times as long as wide).
constexpr RectM kCabinet{3.2, 1.8, 0.6, 2.45};
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
