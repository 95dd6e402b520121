#include "stages/geometry/obstacle_sites.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "tests/support/test_grids.h"

namespace areagraph {
namespace {

using testing::TestGrid;

bool Contains(const std::vector<int>& cells, int index) {
  return std::find(cells.begin(), cells.end(), index) != cells.end();
}

TEST(ObstacleSites, KeepTheRingOfABlockButNotItsInside) {
  TestGrid grid(7, 7);
  grid.Fill(2, 2, 4, 4, proto::CELL_OCCUPIED);
  const std::vector<int> sites = ObstacleSiteCells(grid.cells(), 7, 7);
  EXPECT_EQ(sites.size(), 8u);
  EXPECT_FALSE(Contains(sites, grid.Index(3, 3)));
  EXPECT_TRUE(Contains(sites, grid.Index(2, 2)));
  EXPECT_TRUE(Contains(sites, grid.Index(3, 4)));
  EXPECT_TRUE(std::is_sorted(sites.begin(), sites.end()));
}

TEST(ObstacleSites, ExcludeInteriorCellsOfThickWalls) {
  TestGrid grid(20, 20, proto::CELL_UNKNOWN);
  grid.Fill(3, 3, 16, 16, proto::CELL_FREE).Walls(3, 3, 16, 16, 3);
  const std::vector<int> sites = ObstacleSiteCells(grid.cells(), 20, 20);
  for (int col = 0; col < 20; ++col) EXPECT_FALSE(Contains(sites, grid.Index(col, 4)));
  // Only the inner layer of the 3-cell wall touches free space.
  EXPECT_TRUE(Contains(sites, grid.Index(10, 5)));
  EXPECT_FALSE(Contains(sites, grid.Index(10, 4)));
  EXPECT_FALSE(Contains(sites, grid.Index(10, 3)));
  EXPECT_EQ(sites.size(), size_t(4 * 8 + 4));  // 8x8 free room, inner ring incl. corners
}

TEST(ObstacleSites, IncludeUnknownCellsNextToFreeSpace) {
  TestGrid grid(5, 5);
  grid.Fill(0, 0, 1, 4, proto::CELL_UNKNOWN);
  const std::vector<int> sites = ObstacleSiteCells(grid.cells(), 5, 5);
  EXPECT_EQ(sites.size(), 5u);
  for (int row = 0; row < 5; ++row) {
    EXPECT_TRUE(Contains(sites, grid.Index(1, row)));
    EXPECT_FALSE(Contains(sites, grid.Index(0, row)));
  }
}

TEST(ObstacleSites, DiagonalFreeNeighbourCounts) {
  TestGrid grid(3, 3, proto::CELL_OCCUPIED);
  grid.Fill(2, 2, 2, 2, proto::CELL_FREE);
  const std::vector<int> sites = ObstacleSiteCells(grid.cells(), 3, 3);
  EXPECT_EQ(sites, (std::vector<int>{grid.Index(1, 1), grid.Index(2, 1), grid.Index(1, 2)}));
}

TEST(ObstacleSites, CentresArePixelCentres) {
  TestGrid grid(4, 3);
  grid.Fill(2, 1, 2, 1, proto::CELL_OCCUPIED);
  const std::vector<Eigen::Vector2d> sites = ObstacleSites(grid.cells(), 4, 3);
  ASSERT_EQ(sites.size(), 1u);
  EXPECT_DOUBLE_EQ(sites[0].x(), 2.5);
  EXPECT_DOUBLE_EQ(sites[0].y(), 1.5);
}

}  // namespace
}  // namespace areagraph
