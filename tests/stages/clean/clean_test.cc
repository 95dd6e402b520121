#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <deque>
#include <limits>

#include "common/error.h"
#include "stages/clean/clean_stage.h"
#include "stages/clean/furniture_removal.h"
#include "stages/clean/outlier_removal.h"
#include "tests/support/test_grids.h"

namespace areagraph {
namespace {

using testing::TestGrid;

// A 5 m x 4 m room (0.05 m/px) with 2-cell walls inside unknown space.
TestGrid Room() {
  TestGrid grid(120, 100, proto::CELL_UNKNOWN);
  grid.Fill(10, 10, 109, 89, proto::CELL_FREE).Walls(10, 10, 109, 89, 2);
  return grid;
}

int CountOccupied(const std::string& cells) {
  return int(std::count(cells.begin(), cells.end(), char(proto::CELL_OCCUPIED)));
}

bool Recorded(const proto::CleanedMap& cleaned, int index) {
  const auto& outliers = cleaned.removed_outlier_cells();
  const auto& furniture = cleaned.removed_furniture_cells();
  return std::find(outliers.begin(), outliers.end(), index) != outliers.end() ||
         std::find(furniture.begin(), furniture.end(), index) != furniture.end();
}

proto::CellState At(const proto::CleanedMap& cleaned, int col, int row) {
  return proto::CellState(cleaned.cells()[row * cleaned.frame().width_px() + col]);
}

// Free cells reachable from (col, row) through 4-connected free cells.
int FloodFree(const std::string& cells, int width, int height, int col, int row) {
  std::vector<bool> seen(cells.size(), false);
  std::deque<int> queue{row * width + col};
  seen[queue.front()] = true;
  int count = 0;
  while (!queue.empty()) {
    const int index = queue.front();
    queue.pop_front();
    ++count;
    const int c = index % width, r = index / width;
    const int next[4][2] = {{c + 1, r}, {c - 1, r}, {c, r + 1}, {c, r - 1}};
    for (const auto& n : next) {
      if (n[0] < 0 || n[1] < 0 || n[0] >= width || n[1] >= height) continue;
      const int j = n[1] * width + n[0];
      if (!seen[j] && cells[j] == proto::CELL_FREE) {
        seen[j] = true;
        queue.push_back(j);
      }
    }
  }
  return count;
}

TEST(Clean, KeepsTheWallsOfAnEmptyRoom) {
  const TestGrid room = Room();
  const proto::CleanedMap cleaned = CleanGridMap(room.ToGridMap(), proto::CleanOptions());
  EXPECT_EQ(cleaned.format_version(), 1u);
  EXPECT_EQ(cleaned.frame().width_px(), 120);
  EXPECT_EQ(cleaned.cells(), room.cells());
  EXPECT_EQ(cleaned.removed_outlier_cells_size(), 0);
  EXPECT_EQ(cleaned.removed_furniture_cells_size(), 0);
}

TEST(Clean, RemovesAnIsolatedSpeck) {
  TestGrid room = Room();
  const int walls = CountOccupied(room.cells());
  room.Fill(60, 50, 60, 50, proto::CELL_OCCUPIED);
  const proto::CleanedMap cleaned = CleanGridMap(room.ToGridMap(), proto::CleanOptions());
  EXPECT_EQ(At(cleaned, 60, 50), proto::CELL_FREE);
  EXPECT_TRUE(Recorded(cleaned, room.Index(60, 50)));
  EXPECT_EQ(cleaned.removed_outlier_cells_size() + cleaned.removed_furniture_cells_size(), 1);
  EXPECT_EQ(CountOccupied(cleaned.cells()), walls);
}

TEST(Clean, RemovesAOneMetreFurnitureBlock) {
  TestGrid room = Room();
  const int walls = CountOccupied(room.cells());
  room.Fill(40, 30, 59, 49, proto::CELL_OCCUPIED);  // 20 x 20 cells = 1 m x 1 m
  const proto::CleanedMap cleaned = CleanGridMap(room.ToGridMap(), proto::CleanOptions());
  EXPECT_EQ(CountOccupied(cleaned.cells()), walls);
  ASSERT_EQ(cleaned.removed_furniture_cells_size(), 400);
  EXPECT_EQ(cleaned.removed_furniture_cells(0), room.Index(40, 30));
  EXPECT_EQ(cleaned.removed_furniture_cells(399), room.Index(59, 49));
  ASSERT_EQ(cleaned.furniture_shapes_size(), 1);
  const proto::Ring& outline = cleaned.furniture_shapes(0).outer();
  ASSERT_EQ(outline.points_size(), 4);
  for (const proto::Point2& p : outline.points()) {
    EXPECT_TRUE(p.x() == 40 || p.x() == 60);
    EXPECT_TRUE(p.y() == 30 || p.y() == 50);
  }
}

TEST(Clean, KeepsFurnitureThatIsTooBig) {
  TestGrid room = Room();
  room.Fill(30, 30, 69, 59, proto::CELL_OCCUPIED);  // 2 m x 1.5 m: perimeter 7 m
  const proto::CleanedMap cleaned = CleanGridMap(room.ToGridMap(), proto::CleanOptions());
  EXPECT_EQ(cleaned.removed_furniture_cells_size(), 0);
  EXPECT_EQ(At(cleaned, 50, 45), proto::CELL_OCCUPIED);
}

TEST(Clean, KeepsFurnitureWithinARobotWidthOfAWall) {
  TestGrid room = Room();
  // 0.3 m from the inner face of the top wall: closer than the 0.5 m robot.
  room.Fill(40, 18, 49, 27, proto::CELL_OCCUPIED);
  const proto::CleanedMap cleaned = CleanGridMap(room.ToGridMap(), proto::CleanOptions());
  EXPECT_EQ(cleaned.removed_furniture_cells_size(), 0);
  EXPECT_EQ(At(cleaned, 45, 22), proto::CELL_OCCUPIED);
  // With a narrower robot the gap is passable and the block is furniture.
  proto::CleanOptions narrow;
  narrow.set_robot_width_m(0.2);
  const proto::CleanedMap narrow_cleaned = CleanGridMap(room.ToGridMap(), narrow);
  EXPECT_EQ(narrow_cleaned.removed_furniture_cells_size(), 100);
}

// The room with a wall across it (rows 50-51) with two doors 1 m wide
// (columns 30-49 and 80-99): the piece between them, 1.5 m long, stands free.
TestGrid RoomWithTwoDoors() {
  TestGrid room = Room();
  room.Fill(10, 50, 29, 51, proto::CELL_OCCUPIED).Fill(50, 50, 79, 51, proto::CELL_OCCUPIED);
  room.Fill(100, 50, 109, 51, proto::CELL_OCCUPIED);
  return room;
}

TEST(Clean, KeepsAPieceOfWallBetweenTwoDoors) {
  const TestGrid room = RoomWithTwoDoors();
  const proto::CleanedMap cleaned = CleanGridMap(room.ToGridMap(), proto::CleanOptions());
  EXPECT_EQ(cleaned.removed_furniture_cells_size(), 0);
  EXPECT_EQ(At(cleaned, 65, 50), proto::CELL_OCCUPIED);
  // The paper's step (b) takes it: its perimeter is a desk's.
  proto::CleanOptions paper;
  paper.add_skip_passes(proto::CleanOptions::KEEP_WALL_PIECES);
  const proto::CleanedMap removed = CleanGridMap(room.ToGridMap(), paper);
  EXPECT_EQ(removed.removed_furniture_cells_size(), 60);
  EXPECT_EQ(At(removed, 65, 50), proto::CELL_FREE);
}

TEST(Clean, RemovesThinPiecesThatStandFreeOrAreShortAndThickOnes) {
  // 1 m long, 2 m from either wall: no door beside it.
  TestGrid free_standing = Room();
  free_standing.Fill(50, 50, 69, 51, proto::CELL_OCCUPIED);
  EXPECT_EQ(
      CleanGridMap(free_standing.ToGridMap(), proto::CleanOptions()).removed_furniture_cells_size(),
      40);
  // 0.4 m long between two doors 0.6 m wide.
  TestGrid short_piece = Room();
  short_piece.Fill(10, 50, 43, 51, proto::CELL_OCCUPIED).Fill(56, 50, 63, 51, proto::CELL_OCCUPIED);
  short_piece.Fill(76, 50, 109, 51, proto::CELL_OCCUPIED);
  const proto::CleanedMap short_cleaned =
      CleanGridMap(short_piece.ToGridMap(), proto::CleanOptions());
  for (int col = 56; col <= 63; ++col) {
    EXPECT_EQ(At(short_cleaned, col, 50), proto::CELL_FREE) << col;  // outlier or furniture
  }
  // A desk 1.2 x 0.5 m between the doors: thicker and shorter than a piece of wall.
  TestGrid desk = RoomWithTwoDoors();
  desk.Fill(50, 50, 79, 51, proto::CELL_FREE).Fill(53, 46, 76, 55, proto::CELL_OCCUPIED);
  EXPECT_EQ(CleanGridMap(desk.ToGridMap(), proto::CleanOptions()).removed_furniture_cells_size(),
            240);
}

TEST(Clean, RemovesSmallUnknownIslandsButNeverTheOutline) {
  TestGrid grid(100, 80);
  grid.Fill(0, 0, 99, 0, proto::CELL_OCCUPIED);     // short wall along the border
  grid.Fill(50, 0, 52, 2, proto::CELL_UNKNOWN);     // small, but on the border
  grid.Fill(40, 40, 79, 69, proto::CELL_UNKNOWN);   // 2 m x 1.5 m unexplored area
  grid.Fill(10, 25, 12, 27, proto::CELL_OCCUPIED);  // a small occupied piece
  grid.Fill(20, 50, 23, 53, proto::CELL_UNKNOWN);   // grey furniture (imports as unknown)
  grid.Fill(24, 50, 24, 50, proto::CELL_OCCUPIED);  // with a dark edge
  proto::CleanOptions options;
  options.set_outlier_percent(0);  // furniture only
  const proto::CleanedMap cleaned = CleanGridMap(grid.ToGridMap(), options);
  EXPECT_EQ(At(cleaned, 5, 0), proto::CELL_OCCUPIED);
  EXPECT_EQ(At(cleaned, 51, 2), proto::CELL_UNKNOWN);
  EXPECT_EQ(At(cleaned, 60, 55), proto::CELL_UNKNOWN);
  EXPECT_EQ(At(cleaned, 40, 40), proto::CELL_UNKNOWN);
  EXPECT_EQ(At(cleaned, 11, 26), proto::CELL_FREE);
  EXPECT_EQ(At(cleaned, 21, 51), proto::CELL_FREE);
  EXPECT_EQ(At(cleaned, 24, 50), proto::CELL_FREE);
  EXPECT_EQ(cleaned.removed_furniture_cells_size(), 9 + 16 + 1);
  EXPECT_EQ(cleaned.furniture_shapes_size(), 2);
}

TEST(Clean, FurnitureRegionBoundAdmitsEveryShapeUnderThePerimeter) {
  const double bound = MaxFurnitureRegionCells(5, 80);
  EXPECT_GT(bound, 21 * 21);  // the biggest square: sides of 20 px between centres
  EXPECT_GT(bound, 41);       // the longest line: 2 * 40 px of boundary
  EXPECT_TRUE(std::isinf(MaxFurnitureRegionCells(0.5, 80)));
}

TEST(Clean, KeepsAClosedRoomStandingInFreeSpace) {
  // Maps whose outside was painted free: the walls are one big piece.
  TestGrid grid(140, 120);
  grid.Walls(10, 10, 129, 109, 1);
  const proto::CleanedMap cleaned = CleanGridMap(grid.ToGridMap(), proto::CleanOptions());
  EXPECT_EQ(CountOccupied(cleaned.cells()), CountOccupied(grid.cells()));
}

TEST(Clean, OutliersNeverOpenAWallOrEatThickWalls) {
  // A diamond-shaped room of one-pixel diagonal walls in free space: sparser
  // than a straight wall, so its cells are outlier candidates. Inside, a thick
  // block and a row of single cells. Even with half of all obstacle cells
  // taken as outliers, the room stays closed and the block whole.
  TestGrid grid(140, 120);
  for (int row = 0; row < 120; ++row) {
    for (int col = 0; col < 140; ++col) {
      if (std::abs(col - 70) + std::abs(row - 60) == 40) {
        grid.Fill(col, row, col, row, proto::CELL_OCCUPIED);
      }
    }
  }
  grid.Fill(60, 50, 69, 59, proto::CELL_OCCUPIED);
  for (int col = 50; col <= 85; col += 7) grid.Fill(col, 75, col, 75, proto::CELL_OCCUPIED);
  proto::CleanOptions options;
  options.set_outlier_percent(50);
  options.set_furniture_max_perimeter_m(0);  // outliers only
  const proto::CleanedMap cleaned = CleanGridMap(grid.ToGridMap(), options);
  const int inside = FloodFree(cleaned.cells(), 140, 120, 70, 70);
  const int outside = FloodFree(cleaned.cells(), 140, 120, 0, 0);
  EXPECT_EQ(inside + outside + CountOccupied(cleaned.cells()), 140 * 120);
  for (int row = 50; row <= 59; ++row) {
    for (int col = 60; col <= 69; ++col) EXPECT_EQ(At(cleaned, col, row), proto::CELL_OCCUPIED);
  }
  // The scattered single cells are the outliers that went.
  EXPECT_EQ(cleaned.removed_outlier_cells_size(), 6);
  for (int col = 50; col <= 85; col += 7) {
    EXPECT_EQ(At(cleaned, col, 75), proto::CELL_FREE);
    EXPECT_TRUE(Recorded(cleaned, grid.Index(col, 75)));
  }
}

TEST(Clean, ZeroPercentRemovesNoOutliers) {
  TestGrid room = Room();
  room.Fill(60, 50, 60, 50, proto::CELL_OCCUPIED);
  proto::CleanOptions options;
  options.set_outlier_percent(0);
  const proto::CleanedMap cleaned = CleanGridMap(room.ToGridMap(), options);
  EXPECT_EQ(cleaned.removed_outlier_cells_size(), 0);
  EXPECT_EQ(cleaned.removed_furniture_cells_size(), 1);  // the speck is still furniture
}

TEST(Clean, StraightWallScoreMatchesCgalsDefinition) {
  // k = 3: the point itself, and one neighbour at distance 1 on each side.
  EXPECT_DOUBLE_EQ(StraightWallScore(3), 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(StraightWallScore(5), (1 + 1 + 4 + 4) / 5.0);
}

void ExpectOptionsError(const proto::CleanOptions& options, const std::string& needle) {
  try {
    CleanGridMap(Room().ToGridMap(), options);
    ADD_FAILURE() << "no error for " << options.ShortDebugString();
  } catch (const OptionsError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(needle), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(Clean, RejectsBadOptions) {
  proto::CleanOptions o;
  o.set_outlier_neighbors(1);
  ExpectOptionsError(o, "clean.outlier_neighbors");
  o = {};
  o.set_outlier_percent(100);
  ExpectOptionsError(o, "clean.outlier_percent");
  o.set_outlier_percent(-1);
  ExpectOptionsError(o, "clean.outlier_percent");
  o.set_outlier_percent(std::nan(""));
  ExpectOptionsError(o, "clean.outlier_percent");
  o = {};
  o.set_robot_width_m(0);
  ExpectOptionsError(o, "clean.robot_width_m");
  o.set_robot_width_m(std::numeric_limits<double>::infinity());
  ExpectOptionsError(o, "clean.robot_width_m");
  o.set_robot_width_m(7);  // the map is 6 m wide
  ExpectOptionsError(o, "clean.robot_width_m");
  o = {};
  o.set_furniture_max_perimeter_m(-1);
  ExpectOptionsError(o, "clean.furniture_max_perimeter_m");
}

void ExpectInputError(const proto::GridMap& map, const std::string& needle) {
  try {
    CleanGridMap(map, proto::CleanOptions());
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

TEST(Clean, RejectsMapsWithoutFreeSpaceOrObstacles) {
  ExpectInputError(TestGrid(40, 40, proto::CELL_UNKNOWN).ToGridMap(), "the map has no free space");
  ExpectInputError(TestGrid(40, 40, proto::CELL_FREE).ToGridMap(), "the map has no obstacle");
  proto::GridMap broken = Room().ToGridMap();
  broken.mutable_cells()->pop_back();
  ExpectInputError(broken, "the map has 11999 cells");
  ExpectInputError(Room().ToGridMap(0), "resolution");
}

}  // namespace
}  // namespace areagraph
