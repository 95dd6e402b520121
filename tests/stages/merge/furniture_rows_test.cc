// FurnitureRowCells on drawn rooms: which free-standing long blocks make a
// stack of rows (seats, shelves) and which do not.
#include "stages/merge/furniture_rows.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <vector>

#include "tests/support/area_test_support.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

// merge.furniture_gaps.max_elongation's default: a row is longer than that
// many times its thickness.
constexpr double kMinElongation = 5;

// The row cells FurnitureRowCells finds among `blocks` drawn in one large
// room.
int RowCells(const std::vector<floorplan::RectM>& blocks) {
  floorplan::FloorPlan plan(22, 18);
  floorplan::DrawRoom(plan, {1, 1, 20, 16});
  for (const floorplan::RectM& block : blocks) floorplan::DrawFurniture(plan, block);
  return cv::countNonZero(FurnitureRowCells(CleanDrawnMap(plan.image()), kMinElongation));
}

// Three blocks 8 x 0.5 m, their tops `pitch_m` apart.
std::vector<floorplan::RectM> ThreeRows(double pitch_m) {
  std::vector<floorplan::RectM> rows;
  for (int k = 0; k < 3; ++k) rows.push_back({5, 3 + k * pitch_m, 8, 0.5});
  return rows;
}

TEST(FurnitureRowsTest, ThreeRowsSideBySideAreAStack) { EXPECT_GT(RowCells(ThreeRows(1.1)), 0); }

TEST(FurnitureRowsTest, BlocksWithRoomsBetweenThemAreNoStack) {
  // 4 m apart: pieces of wall with a room between each two, not rows
  // (kMaxRowPitchM).
  EXPECT_EQ(RowCells(ThreeRows(4)), 0);
}

TEST(FurnitureRowsTest, BlocksEndToEndAreNoStack) {
  // Three blocks on one line with 1 m gaps: a broken wall, not rows side by
  // side (they do not overlap along their axis).
  EXPECT_EQ(RowCells({{2, 8, 5, 0.5}, {8, 8, 5, 0.5}, {14, 8, 5, 0.5}}), 0);
}

}  // namespace
}  // namespace areagraph::testing
