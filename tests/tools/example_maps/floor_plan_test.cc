// The floor plan drawing library and the example maps it made.
#include "tools/example_maps/floor_plan.h"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

#include "stages/common/grid_cells.h"
#include "stages/import/grid_map_decoder.h"
#include "stages/import/import_stage.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using namespace floorplan;
using testing::SourcePath;
using testing::TempDir;

uint8_t At(const FloorPlan& plan, int x, int y) { return plan.image().at<uint8_t>(y, x); }

TEST(FloorPlanTest, RoomHasCentredWallsAndFreeInside) {
  FloorPlan plan(4, 4);  // 80x80 px, walls 3 px
  DrawRoom(plan, {1, 1, 2, 2});
  // Outline at pixel 20 and 60: walls on 19..21 and 59..61, free 22..58.
  EXPECT_EQ(At(plan, 18, 40), kUnknownGrey);
  EXPECT_EQ(At(plan, 19, 40), kWallGrey);
  EXPECT_EQ(At(plan, 21, 40), kWallGrey);
  EXPECT_EQ(At(plan, 22, 40), kFreeGrey);
  EXPECT_EQ(At(plan, 58, 40), kFreeGrey);
  EXPECT_EQ(At(plan, 59, 40), kWallGrey);
  EXPECT_EQ(At(plan, 62, 40), kUnknownGrey);
  EXPECT_EQ(cv::countNonZero(plan.image() == kFreeGrey), 37 * 37);
}

TEST(FloorPlanTest, NeighbouringRoomsShareOneWallAndADoorOpensIt) {
  FloorPlan plan(6, 3);
  DrawRoom(plan, {0.5, 0.5, 2.5, 2});
  DrawRoom(plan, {3, 0.5, 2.5, 2});
  EXPECT_EQ(At(plan, 58, 30), kFreeGrey);
  EXPECT_EQ(At(plan, 59, 30), kWallGrey);
  EXPECT_EQ(At(plan, 61, 30), kWallGrey);
  EXPECT_EQ(At(plan, 62, 30), kFreeGrey);
  DrawDoor(plan, 3, 1.5, 0.9, WallDirection::kVertical);
  // Door rows 21..38 (0.9 m = 18 px around row 30) are open across the wall.
  for (int x = 59; x <= 61; ++x) {
    EXPECT_EQ(At(plan, x, 21), kFreeGrey);
    EXPECT_EQ(At(plan, x, 38), kFreeGrey);
    EXPECT_EQ(At(plan, x, 20), kWallGrey);
    EXPECT_EQ(At(plan, x, 39), kWallGrey);
  }
}

TEST(FloorPlanTest, RegionIsWalledOnlyAroundItsOutline) {
  FloorPlan plan(8, 8);
  DrawRegion(plan, {{1, 1, 6, 2}, {1, 1, 2, 6}});  // an L
  // Where the two parts overlap no wall is drawn.
  EXPECT_EQ(At(plan, 60, 40), kFreeGrey);  // x 3 m, inside the horizontal part
  EXPECT_EQ(At(plan, 40, 60), kFreeGrey);  // y 3 m, inside the vertical part
  EXPECT_EQ(At(plan, 60, 60), kWallGrey);  // the inner corner
  EXPECT_EQ(At(plan, 100, 100), kUnknownGrey);
}

TEST(FloorPlanTest, MazeConnectsEveryCell) {
  FloorPlan plan(11, 11);
  DrawMaze(plan, {0.5, 0.5, 10, 10}, 5, 5, /*seed=*/7);
  // All free pixels form one 4-connected component.
  cv::Mat free = plan.image() == kFreeGrey, labels;
  EXPECT_EQ(cv::connectedComponents(free, labels, 4), 2);
  // A perfect 5x5 maze opens 24 of the 40 inner walls: free area = 25 cell
  // insides + 24 openings.
  const int inside = 40 - 3, opening = 37 * 3;
  EXPECT_EQ(cv::countNonZero(free), 25 * inside * inside + 24 * opening);
  FloorPlan again(11, 11);
  DrawMaze(again, {0.5, 0.5, 10, 10}, 5, 5, 7);
  EXPECT_EQ(cv::countNonZero(again.image() != plan.image()), 0);
}

TEST(FloorPlanTest, NoiseDotsAreDeterministicAndOnlyOnFreeCells) {
  FloorPlan a(6, 6), b(6, 6);
  DrawRoom(a, {1, 1, 4, 4});
  DrawRoom(b, {1, 1, 4, 4});
  const int free_before = cv::countNonZero(a.image() == kFreeGrey);
  DrawNoiseDots(a, 25, 11);
  DrawNoiseDots(b, 25, 11);
  EXPECT_EQ(cv::countNonZero(a.image() != b.image()), 0);
  EXPECT_EQ(cv::countNonZero(a.image() == kFreeGrey), free_before - 25);
  EXPECT_EQ(cv::countNonZero(a.image() == kUnknownGrey),
            cv::countNonZero(b.image() == kUnknownGrey));
}

// The examples in the repository are what the generator draws today.
TEST(ExampleMapsTest, GeneratorReproducesTheExamples) {
  TempDir dir;
  const testing::CommandResult run =
      testing::RunTool("ag-make-example-maps", {"--out", dir.path()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* name : {"two_rooms.png", "corridor_rooms.png", "office_small.png"}) {
    const cv::Mat made = cv::imread(dir.File(name), cv::IMREAD_UNCHANGED);
    const cv::Mat shipped =
        cv::imread(SourcePath(std::string("examples/") + name), cv::IMREAD_UNCHANGED);
    ASSERT_FALSE(shipped.empty()) << name;
    ASSERT_EQ(made.size(), shipped.size()) << name;
    EXPECT_EQ(cv::countNonZero(made != shipped), 0) << name;
  }
  EXPECT_EQ(testing::ReadFile(dir.File("office_small.yaml")),
            testing::ReadFile(SourcePath("examples/office_small.yaml")));
}

TEST(ExampleMapsTest, ExamplesImportWithAllThreeClasses) {
  const struct {
    const char* file;
    int width, height;
  } examples[] = {{"two_rooms.png", 240, 140},
                  {"corridor_rooms.png", 400, 240},
                  {"office_small.yaml", 360, 300}};
  for (const auto& example : examples) {
    SCOPED_TRACE(example.file);
    const proto::GridMap grid =
        ImportGridMap(ReadImportSource(SourcePath(std::string("examples/") + example.file)),
                      proto::ImportOptions());
    EXPECT_EQ(grid.frame().width_px(), example.width);
    EXPECT_EQ(grid.frame().height_px(), example.height);
    const CellCounts counts = CountCells(grid.cells());
    EXPECT_GT(counts.free, counts.unknown);
    EXPECT_GT(counts.unknown, counts.occupied);
    EXPECT_GT(counts.occupied, 0);
  }
}

}  // namespace
}  // namespace areagraph
