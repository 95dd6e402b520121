// clean pass KEEP_WALL_PIECES: WallPieceRegions measures depths only where a
// decision needs them, and must decide as the whole map's depth does.
#include "stages/clean/wall_pieces.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <random>

#include "stages/geometry/furniture_shape.h"
#include "stages/geometry/obstacle_regions.h"
#include "stages/geometry/wall_thickness.h"
#include "tests/support/test_grids.h"

namespace areagraph {
namespace {

using testing::TestGrid;

// The decision on the whole map's depth and every region's shape.
std::vector<uint8_t> WholeMapWallPieces(const std::string& cells, int width, int height,
                                        const cv::Mat& labels, int count,
                                        const std::vector<int>& candidates,
                                        const WallPieceSizes& sizes, int* by_typical) {
  const ObstacleRegions regions = DescribeObstacleRegions(
      labels.clone(), count, ObstacleDepth(ObstacleMask(cells, width, height)), candidates);
  const double thinner_than =
      std::max(sizes.thinner_than_px,
               kFurnitureWallRatio * TypicalWallThickness(regions.depth, sizes.max_wall_px));
  std::vector<uint8_t> wall(count, 0);
  for (int region = 1; region < count; ++region) {
    const RegionShape& shape = regions.shapes[region];
    if (shape.on_border || shape.length == 0) continue;
    bool ends = true;
    for (const int direction : {1, -1}) {
      bool meets = false;
      for (const int offset : {0, -1, 1}) {
        const Eigen::Vector2d along = direction * shape.axis;
        const Eigen::Vector2d end = shape.centre + 0.5 * shape.length * along +
                                    offset * Eigen::Vector2d(-along.y(), along.x());
        for (double t = 0; t <= sizes.max_gap_px && !meets; t += 1) {
          const int label = regions.LabelAt(end + t * along);
          meets = label != 0 && label != region;
        }
      }
      ends = ends && meets;
    }
    wall[region] = shape.thickness < thinner_than && shape.length >= sizes.min_length_px &&
                   shape.length >= kWallPieceElongation * shape.width && ends;
    *by_typical += wall[region] && shape.thickness >= sizes.thinner_than_px;
  }
  return wall;
}

// Rooms split by walls of 1 to 4 cells with door gaps (which leave wall
// pieces), desks and clutter, inside an outline wall.
TestGrid RandomRooms(std::mt19937& random, int width, int height) {
  TestGrid grid(width, height, proto::CELL_FREE);
  auto uniform = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(random); };
  grid.Walls(0, 0, width - 1, height - 1, uniform(1, 3));
  for (int wall = uniform(2, 6); wall > 0; --wall) {
    const int thickness = uniform(1, 4);
    const bool across = uniform(0, 1);
    const int at = uniform(8, (across ? width : height) - 9);
    const int length = across ? height : width;
    for (int from = 0; from < length;) {
      const int to = std::min(length - 1, from + uniform(6, 40));
      if (across) {
        grid.Fill(at, from, at + thickness - 1, to, proto::CELL_OCCUPIED);
      } else {
        grid.Fill(from, at, to, at + thickness - 1, proto::CELL_OCCUPIED);
      }
      from = to + uniform(4, 18);
    }
  }
  for (int desk = uniform(3, 12); desk > 0; --desk) {
    const int col = uniform(3, width - 12), row = uniform(3, height - 12);
    grid.Fill(col, row, col + uniform(0, 8), row + uniform(0, 8),
              uniform(0, 1) ? proto::CELL_OCCUPIED : proto::CELL_UNKNOWN);
  }
  for (int dot = uniform(0, 40); dot > 0; --dot) {
    const int col = uniform(2, width - 3), row = uniform(2, height - 3);
    grid.Fill(col, row, col, row, proto::CELL_OCCUPIED);
  }
  return grid;
}

// Every cell of a random choice of the regions off the image border, in
// row-major order, as RemoveFurniture passes its furniture pieces.
std::vector<int> SomeRegionsCells(std::mt19937& random, const cv::Mat& labels, int count) {
  std::vector<uint8_t> chosen(count, 0);
  for (int region = 1; region < count; ++region) chosen[region] = random() % 4 != 0;
  for (int c = 0; c < labels.cols; ++c) {
    chosen[labels.at<int>(0, c)] = chosen[labels.at<int>(labels.rows - 1, c)] = 0;
  }
  for (int r = 0; r < labels.rows; ++r) {
    chosen[labels.at<int>(r, 0)] = chosen[labels.at<int>(r, labels.cols - 1)] = 0;
  }
  std::vector<int> cells;
  const int* label = labels.ptr<int>();
  for (int index = 0; index < labels.rows * labels.cols; ++index) {
    if (chosen[label[index]]) cells.push_back(index);
  }
  return cells;
}

void ExpectSameAsWholeMap(std::mt19937& random, int width, int height, int* walls,
                          int* by_typical) {
  const TestGrid grid = RandomRooms(random, width, height);
  cv::Mat labels;
  const int count =
      cv::connectedComponents(ObstacleMask(grid.cells(), width, height), labels, 8, CV_32S);
  const std::vector<int> candidates = SomeRegionsCells(random, labels, count);
  for (const double thinner_than : {1.0, 3.0, 6.0}) {
    WallPieceSizes sizes;
    sizes.thinner_than_px = thinner_than;
    sizes.min_length_px = 4 + random() % 8;
    sizes.max_gap_px = 6 + random() % 20;
    sizes.max_wall_px = 4 + random() % 16;
    const std::vector<uint8_t> wall =
        WallPieceRegions(grid.cells(), width, height, labels, count, candidates, sizes);
    ASSERT_EQ(wall, WholeMapWallPieces(grid.cells(), width, height, labels, count, candidates,
                                       sizes, by_typical));
    for (int region = 1; region < count; ++region) *walls += wall[region];
  }
}

TEST(WallPieces, DecideAsTheWholeMapsDepth) {
  std::mt19937 random(14);
  int walls = 0, by_typical = 0;
  for (int round = 0; round < 60; ++round) {
    ExpectSameAsWholeMap(random, 60 + int(random() % 140), 50 + int(random() % 100), &walls,
                         &by_typical);
  }
  // The maps do hold wall pieces, also ones only the typical wall makes thin.
  EXPECT_GT(walls, 20);
  EXPECT_GT(by_typical, 5);
}

// Beyond 4097 cells across the map's depth is OpenCV's single-precision
// one, which a box does not reproduce: the regions take it from the map.
TEST(WallPieces, DecideAsTheWholeMapsDepthOnAWideMap) {
  std::mt19937 random(15);
  int walls = 0, by_typical = 0;
  ExpectSameAsWholeMap(random, 4200, 40, &walls, &by_typical);
  EXPECT_GT(walls, 0);
}

}  // namespace
}  // namespace areagraph
