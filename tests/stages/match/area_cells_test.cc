// RasterizeAreas and CountOverlaps: cells by their centres, polygons that
// tile the plane share no cell, holes stay out, other frames line up.
#include "stages/match/area_cells.h"

#include <gtest/gtest.h>

#include "tests/stages/match/synthetic_graphs.h"

namespace areagraph::testing {
namespace {

TEST(AreaCellsTest, CountsTheCellsWhoseCentresLieInside) {
  // 2 m x 1 m and its neighbour: 40 x 20 and 20 x 20 cells, none shared.
  const AreaCells cells =
      RasterizeAreas(RectGraph(Frame(100, 60), {{0, 0, 2, 1}, {2, 0, 3, 1}}), Frame(100, 60));
  EXPECT_EQ(cells.cells, (std::vector<int64_t>{800, 400}));
  int64_t in_rows = 0;
  for (const auto& row : cells.rows) {
    for (const CellRun& run : row) in_rows += run.x1 - run.x0;
  }
  EXPECT_EQ(in_rows, 1200);
}

TEST(AreaCellsTest, HolesAreLeftOutAndTheFrameClips) {
  proto::AreaGraph graph = RectGraph(Frame(100, 60), {{-1, 0, 3, 2}});
  // A 1 m x 1 m hole (clockwise or not: even-odd).
  proto::Ring* hole = graph.mutable_areas(0)->mutable_polygon_m()->add_holes();
  for (const auto& [x, y] :
       std::vector<std::pair<double, double>>{{1, 1}, {1, 0.5}, {2, 0.5}, {2, 1.5}, {1, 1.5}}) {
    proto::Point2* point = hole->add_points();
    point->set_x(x);
    point->set_y(y);
  }
  // Inside the 100 x 60 frame from x = 0: 3 m x 2 m = 2400 cells, less 400.
  EXPECT_EQ(RasterizeAreas(graph, Frame(100, 60)).cells, (std::vector<int64_t>{2000}));
}

TEST(AreaCellsTest, OverlapsAreCountedOnTheSecondGraphsGrid) {
  const proto::AreaGraph before = RectGraph(Frame(100, 60), {{0, 0, 2, 1}, {2, 0, 3, 1}});
  const proto::AreaGraph after = RectGraph(Frame(140, 80, -1, -1), {{0, 0, 2.5, 1}});
  const proto::MapFrame& grid = after.frame();
  const std::vector<AreaOverlap> overlaps =
      CountOverlaps(RasterizeAreas(before, grid), RasterizeAreas(after, grid));
  ASSERT_EQ(overlaps.size(), 2u);
  EXPECT_EQ(overlaps[0].before, 0);
  EXPECT_EQ(overlaps[0].after, 0);
  EXPECT_EQ(overlaps[0].cells, 800);
  EXPECT_EQ(overlaps[1].before, 1);
  EXPECT_EQ(overlaps[1].cells, 200);
}

}  // namespace
}  // namespace areagraph::testing
