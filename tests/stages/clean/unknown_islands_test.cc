// clean.unknown_island_max_m2: small unknown islands in mapped space become
// free before outlier and furniture removal.
#include "stages/clean/unknown_islands.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <random>

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

// OpenCV's 8-connected labelling of the unknown cells and its statistics.
std::vector<int> IslandsByOpenCv(const std::string& cells, int width, int height,
                                 double max_cells) {
  cv::Mat unknown(height, width, CV_8U), labels, stats, centroids;
  for (int index = 0; index < width * height; ++index) {
    unknown.data[index] = cells[index] == char(proto::CELL_UNKNOWN) ? 255 : 0;
  }
  const int count = cv::connectedComponentsWithStats(unknown, labels, stats, centroids, 8, CV_32S);
  std::vector<int> islands;
  for (int index = 0; index < width * height; ++index) {
    const int label = labels.ptr<int>()[index];
    if (label == 0 || label >= count) continue;
    const int x = stats.at<int>(label, cv::CC_STAT_LEFT), y = stats.at<int>(label, cv::CC_STAT_TOP);
    const int w = stats.at<int>(label, cv::CC_STAT_WIDTH);
    const int h = stats.at<int>(label, cv::CC_STAT_HEIGHT);
    const bool on_border = x == 0 || y == 0 || x + w == width || y + h == height;
    if (!on_border && stats.at<int>(label, cv::CC_STAT_AREA) <= max_cells) islands.push_back(index);
  }
  return islands;
}

TEST(UnknownIslands, SameAsOpenCvsLabelling) {
  std::mt19937 random(12);
  for (int trial = 0; trial < 80; ++trial) {
    const int width = 1 + int(random() % 70), height = 1 + int(random() % 50);
    std::string cells(size_t(width) * height, char(proto::CELL_FREE));
    // Blobs, thin diagonal chains (8-connected only) and occupied cells.
    for (int blob = int(random() % 25); blob > 0; --blob) {
      const int col = int(random() % width), row = int(random() % height);
      const int w = 1 + int(random() % 9), h = 1 + int(random() % 4);
      for (int r = row; r < std::min(height, row + h); ++r) {
        for (int c = col; c < std::min(width, col + w); ++c) {
          if (random() % 5 != 0) cells[r * width + c] = char(proto::CELL_UNKNOWN);
        }
      }
    }
    for (int chain = int(random() % 4); chain > 0; --chain) {
      int col = int(random() % width), row = int(random() % height);
      for (int step = 0; step < 12 && col < width && row < height; ++step, ++col, ++row) {
        cells[row * width + col] = char(proto::CELL_UNKNOWN);
      }
    }
    for (int index = 0; index < width * height; ++index) {
      if (random() % 11 == 0) cells[index] = char(proto::CELL_OCCUPIED);
    }
    const double max_cells = double(random() % 40);
    std::string freed_cells = cells;
    const std::vector<int> freed = FreeUnknownIslands(freed_cells, width, height, max_cells);
    const std::vector<int> expected =
        max_cells > 0 ? IslandsByOpenCv(cells, width, height, max_cells) : std::vector<int>{};
    ASSERT_EQ(freed, expected) << width << " x " << height;
    for (const int index : freed) cells[index] = char(proto::CELL_FREE);
    EXPECT_EQ(freed_cells, cells);
  }
}

}  // namespace
}  // namespace areagraph
