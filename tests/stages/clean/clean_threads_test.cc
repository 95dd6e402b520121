// Clean's compute on one pool thread and on two: the same bytes.
#include <gtest/gtest.h>

#include <random>

#include "stages/clean/clean_stage.h"
#include "tests/support/test_grids.h"
#include "tests/support/thread_count.h"

namespace areagraph {
namespace {

// Rooms with desks, chairs (unknown and occupied), lone specks and scan
// noise: tens of thousands of occupied cells and thousands of alpha-shape
// points, enough for every parallel path.
testing::TestGrid ClutteredRooms(std::mt19937& random, int width, int height) {
  testing::TestGrid grid(width, height, proto::CELL_UNKNOWN);
  auto uniform = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(random); };
  grid.Fill(4, 4, width - 5, height - 5, proto::CELL_FREE).Walls(4, 4, width - 5, height - 5, 2);
  for (int col = 80; col < width - 40; col += 90) {
    grid.Fill(col, 4, col + 1, height - 5, proto::CELL_OCCUPIED);
    grid.Fill(col, height / 2, col + 1, height / 2 + 18, proto::CELL_FREE);  // a door
  }
  for (int desk = 0; desk < 160; ++desk) {
    const int col = uniform(8, width - 20), row = uniform(8, height - 20);
    grid.Fill(col, row, col + uniform(0, 10), row + uniform(0, 10),
              uniform(0, 2) ? proto::CELL_OCCUPIED : proto::CELL_UNKNOWN);
  }
  for (int speck = 0; speck < 600; ++speck) {
    const int col = uniform(6, width - 7), row = uniform(6, height - 7);
    grid.Fill(col, row, col, row, proto::CELL_OCCUPIED);
  }
  return grid;
}

TEST(CleanThreads, OneThreadAndTwoGiveTheSameMap) {
  std::mt19937 random(21);
  const testing::TestGrid grid = ClutteredRooms(random, 900, 600);
  const proto::GridMap map = grid.ToGridMap();
  proto::CleanedMap one, two;
  {
    testing::ThreadCount threads(1);
    one = CleanGridMap(map, proto::CleanOptions());
  }
  {
    testing::ThreadCount threads(2);
    two = CleanGridMap(map, proto::CleanOptions());
  }
  EXPECT_GT(one.removed_outlier_cells_size(), 100);
  EXPECT_GT(one.furniture_shapes_size(), 50);
  EXPECT_EQ(one.SerializeAsString(), two.SerializeAsString());
}

}  // namespace
}  // namespace areagraph
