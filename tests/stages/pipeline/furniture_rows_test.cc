// merge's JOIN_FURNITURE_ROWS through the whole pipeline: a lecture hall's
// rows of seats, each too long and thin for a furniture island, no longer cut
// the hall into a strip between every two rows; two such blocks alone are no
// stack and change nothing.
#include <gtest/gtest.h>

#include <set>

#include "tests/support/area_test_support.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using floorplan::RectM;
using floorplan::WallDirection;

// A 12 x 12 m hall above a 2 m corridor, joined by a 1.2 m door; a 4 x 4 m
// office beside the hall with its own 0.9 m doors to both. Rows of seats 0.5 m deep
// and 9.6 m long stand 1.1 m apart from y = 4 m on, with 1.2 m side aisles.
constexpr RectM kHall{1, 1, 12, 12};
constexpr RectM kOffice{13, 1, 4, 4};
constexpr RectM kCorridor{1, 13, 16, 2};
constexpr double kFirstRowY = 4, kRowPitch = 1.1, kSeatDepth = 0.5;
constexpr double kRowX = kHall.x + 1.2, kRowLength = kHall.width - 2 * 1.2;

floorplan::FloorPlan HallWithRows(int rows) {
  floorplan::FloorPlan plan(18, 16);
  floorplan::DrawRoom(plan, kHall);
  floorplan::DrawRoom(plan, kOffice);
  floorplan::DrawRoom(plan, kCorridor);
  floorplan::DrawDoor(plan, 6, kCorridor.y, 1.2, WallDirection::kHorizontal);
  floorplan::DrawDoor(plan, 14, kCorridor.y, 0.9, WallDirection::kHorizontal);
  // A way through the hall into the office: the hall has two exits, as a
  // corridor has.
  floorplan::DrawDoor(plan, kOffice.x, 2, 0.9, WallDirection::kVertical);
  for (int k = 0; k < rows; ++k) {
    floorplan::DrawFurniture(plan, {kRowX, kFirstRowY + k * kRowPitch, kRowLength, kSeatDepth});
  }
  return plan;
}

// The areas at the stage in front of the rows, in the strips between the
// first `rows` rows, in the side aisle and behind the last row, and the
// corridor's.
struct HallAreas {
  std::set<int> hall;
  int front = -1, corridor = -1;
  int front_kind = -1;
};

HallAreas AreasOf(const floorplan::FloorPlan& plan, int rows,
                  const proto::PipelineOptions& options) {
  const proto::CleanedMap map = CleanDrawnMap(plan.image());
  const AreaStages stages = RunAreaStages(map, options);
  ExpectAreaGraphInvariants(stages, map, 0.9);
  HallAreas areas;
  areas.front = AreaAt(stages.areas, 7, 2.5);
  areas.hall.insert(areas.front);
  const double middle = kRowX + kRowLength / 2;
  for (int k = 0; k + 1 < rows; ++k) {
    areas.hall.insert(AreaAt(stages.areas, middle, kFirstRowY + k * kRowPitch + 0.8));
  }
  areas.hall.insert(AreaAt(stages.areas, kHall.x + 0.6, 7));
  areas.hall.insert(AreaAt(stages.areas, 7, 12));
  areas.corridor = AreaAt(stages.areas, 9, 14);
  for (const proto::Area& area : stages.areas.areas()) {
    if (area.id() == areas.front) areas.front_kind = area.kind();
  }
  return areas;
}

constexpr int kStack = 6;

TEST(FurnitureRowsTest, RowsOfSeatsDoNotCutTheHallIntoStrips) {
  const HallAreas areas = AreasOf(HallWithRows(kStack), kStack, {});
  ASSERT_NE(areas.front, -1);
  ASSERT_NE(areas.corridor, -1);
  EXPECT_EQ(areas.hall, std::set<int>{areas.front});
  EXPECT_NE(areas.front, areas.corridor);
  // The strips between the rows do not make the hall a corridor.
  EXPECT_EQ(areas.front_kind, static_cast<int>(proto::AREA_ROOM));
}

TEST(FurnitureRowsTest, WithoutTheRuleTheStripsBetweenRowsAreAreas) {
  proto::PipelineOptions options;
  options.mutable_merge()->add_skip_passes(proto::MergeOptions::JOIN_FURNITURE_ROWS);
  const HallAreas areas = AreasOf(HallWithRows(kStack), kStack, options);
  EXPECT_GT(areas.hall.size(), 2u);
}

TEST(FurnitureRowsTest, TwoLongBlocksAreNoStack) {
  proto::PipelineOptions without;
  without.mutable_merge()->add_skip_passes(proto::MergeOptions::JOIN_FURNITURE_ROWS);
  const HallAreas with_rule = AreasOf(HallWithRows(2), 2, {});
  const HallAreas without_rule = AreasOf(HallWithRows(2), 2, without);
  EXPECT_EQ(with_rule.hall, without_rule.hall);
}

}  // namespace
}  // namespace areagraph::testing
