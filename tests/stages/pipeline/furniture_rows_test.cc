// merge's JOIN_FURNITURE_ROWS through the whole pipeline: a lecture hall's
// rows of seats, each too long and thin for a furniture island, no longer cut
// the hall into a strip between every two rows; two such blocks alone are no
// stack and change nothing.
#include <gtest/gtest.h>

#include <set>

#include "tests/support/area_test_support.h"
#include "tests/support/merge_pass_cases.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

// HallWithSeatRows (tests/support/merge_pass_cases.h): the rows span
// x = 2.2-11.8 m.
constexpr double kRowX = 2.2, kRowLength = 9.6, kHallX = 1;

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
    areas.hall.insert(AreaAt(stages.areas, middle, kFirstSeatRowY + k * kSeatRowPitch + 0.8));
  }
  areas.hall.insert(AreaAt(stages.areas, kHallX + 0.6, 7));
  areas.hall.insert(AreaAt(stages.areas, 7, 12));
  areas.corridor = AreaAt(stages.areas, 9, 14);
  for (const proto::Area& area : stages.areas.areas()) {
    if (area.id() == areas.front) areas.front_kind = area.kind();
  }
  return areas;
}

constexpr int kStack = 6;

TEST(FurnitureRowsTest, RowsOfSeatsDoNotCutTheHallIntoStrips) {
  const HallAreas areas = AreasOf(HallWithSeatRows(kStack), kStack, {});
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
  const HallAreas areas = AreasOf(HallWithSeatRows(kStack), kStack, options);
  EXPECT_GT(areas.hall.size(), 2u);
}

TEST(FurnitureRowsTest, TwoLongBlocksAreNoStack) {
  proto::PipelineOptions without;
  without.mutable_merge()->add_skip_passes(proto::MergeOptions::JOIN_FURNITURE_ROWS);
  const HallAreas with_rule = AreasOf(HallWithSeatRows(2), 2, {});
  const HallAreas without_rule = AreasOf(HallWithSeatRows(2), 2, without);
  EXPECT_EQ(with_rule.hall, without_rule.hall);
}

}  // namespace
}  // namespace areagraph::testing
