// clean.unknown_island_max_m2: small unknown islands in mapped space become
// free before outlier and furniture removal.
#include "stages/clean/unknown_islands.h"

#include <gtest/gtest.h>

#include "stages/clean/clean_stage.h"
#include "tests/support/test_grids.h"

namespace areagraph {
namespace {

using testing::TestGrid;

// A 6 m x 5 m room (0.05 m/px) inside unknown space with a grid of 6 x 6
// chairs drawn in grey (unknown), each 3 x 3 cells and 0.35 m apart: closer
// than the robot width, so furniture removal takes them as one piece whose
// outline is far longer than clean.furniture_max_perimeter_m.
TestGrid RoomWithChairs() {
  TestGrid grid(140, 120, proto::CELL_UNKNOWN);
  grid.Fill(10, 10, 129, 109, proto::CELL_FREE).Walls(10, 10, 129, 109, 2);
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      grid.Fill(30 + 7 * i, 30 + 7 * j, 32 + 7 * i, 32 + 7 * j, proto::CELL_UNKNOWN);
    }
  }
  return grid;
}

TEST(UnknownIslands, ChairsDrawnInGreyBecomeFree) {
  const TestGrid room = RoomWithChairs();
  proto::CleanOptions options;
  options.set_outlier_percent(0);
  const proto::CleanedMap cleaned = CleanGridMap(room.ToGridMap(), options);
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(cleaned.cells()[room.Index(31 + 7 * i, 31)], char(proto::CELL_FREE));
  }
  // Recorded as removed furniture; the unknown outside and the walls stay.
  EXPECT_EQ(cleaned.removed_furniture_cells_size(), 36 * 9);
  EXPECT_EQ(cleaned.cells()[room.Index(2, 2)], char(proto::CELL_UNKNOWN));
  EXPECT_EQ(cleaned.cells()[room.Index(10, 50)], char(proto::CELL_OCCUPIED));

  // Without it (the paper) the chairs are one big obstacle piece and stay.
  options.set_unknown_island_max_m2(0);
  const proto::CleanedMap kept = CleanGridMap(room.ToGridMap(), options);
  EXPECT_EQ(kept.cells()[room.Index(31, 31)], char(proto::CELL_UNKNOWN));
  EXPECT_EQ(kept.removed_furniture_cells_size(), 0);
}

TEST(UnknownIslands, BigOrBorderTouchingUnknownStays) {
  TestGrid grid(100, 80);
  grid.Fill(40, 30, 59, 49, proto::CELL_UNKNOWN);  // 1 m x 1 m: above 0.25 m2
  grid.Fill(10, 10, 14, 14, proto::CELL_UNKNOWN);  // 0.0625 m2 island
  grid.Fill(0, 60, 3, 63, proto::CELL_UNKNOWN);    // small, but on the border
  std::string cells = grid.cells();
  const std::vector<int> freed = FreeUnknownIslands(cells, 100, 80, 0.25 / (0.05 * 0.05));
  EXPECT_EQ(freed.size(), 25u);
  EXPECT_EQ(cells[grid.Index(12, 12)], char(proto::CELL_FREE));
  EXPECT_EQ(cells[grid.Index(50, 40)], char(proto::CELL_UNKNOWN));
  EXPECT_EQ(cells[grid.Index(1, 61)], char(proto::CELL_UNKNOWN));
  // A limit of 0 frees nothing.
  std::string unchanged = grid.cells();
  EXPECT_TRUE(FreeUnknownIslands(unchanged, 100, 80, 0).empty());
  EXPECT_EQ(unchanged, grid.cells());
}

}  // namespace
}  // namespace areagraph
