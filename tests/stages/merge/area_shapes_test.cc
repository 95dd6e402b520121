// The shape model (RasterShape, MeasureAreaShapes, IsCorridorShaped),
// FurnitureIslandCells and the hole filling they share, on drawn rasters.
#include "stages/merge/area_shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <random>

#include "stages/geometry/corridor_shape.h"
#include "stages/geometry/enclosed_pockets.h"
#include "stages/merge/furniture_islands.h"
#include "tests/stages/merge/hand_made_cut_graph.h"
#include "tests/support/area_test_support.h"

namespace areagraph::testing {
namespace {

constexpr double kResolutionM = 0.05;
// cut.islands.max_length_m's default, which the CutGraph carries to merge.
constexpr double kIslandMaxM = 4.0;

// A raster of `rects` (area k + 1 on rects[k]) at 0.05 m/px.
AreaRaster RasterOf(const std::vector<cv::Rect>& rects) {
  AreaRaster raster;
  raster.labels = cv::Mat::zeros(400, 600, CV_32S);
  for (size_t k = 0; k < rects.size(); ++k) {
    raster.labels(rects[k]).setTo(static_cast<int>(k + 1));
  }
  raster.cell_count.resize(rects.size());
  CountAreaCells(&raster);
  return raster;
}

TEST(RasterShapeTest, CorridorsAreLongAgainstTheirWidestSpot) {
  // A corridor 2 x 10 m; a room 4 x 5 m; a hall 5 x 25 m (wider than a
  // corridor); an L of two arms 1.5 m wide and 6 m long.
  AreaRaster raster = RasterOf({{0, 0, 200, 40}, {0, 50, 100, 80}, {0, 140, 500, 100}});
  raster.labels(cv::Rect(520, 0, 30, 120)).setTo(4);
  raster.labels(cv::Rect(400, 90, 120, 30)).setTo(4);
  raster.cell_count.resize(4);
  CountAreaCells(&raster);
  const AreaShape corridor = RasterShape(raster, 0, kResolutionM, kIslandMaxM);
  EXPECT_NEAR(corridor.typical_px, 40, 2);
  EXPECT_NEAR(corridor.widest_px, 40, 2);
  EXPECT_TRUE(corridor.corridor);
  EXPECT_FALSE(RasterShape(raster, 1, kResolutionM, kIslandMaxM).corridor);
  const AreaShape hall = RasterShape(raster, 2, kResolutionM, kIslandMaxM);
  EXPECT_GT(hall.typical_px * kResolutionM, kMaxCorridorWidthM);
  EXPECT_FALSE(hall.corridor);
  EXPECT_TRUE(RasterShape(raster, 3, kResolutionM, kIslandMaxM).corridor);
}

TEST(RasterShapeTest, DesksAreFilledTheRoomsInsideALoopAreNot) {
  // A room 8 x 6 m with three desks 1.6 x 0.8 m standing free in it: the
  // paths between them are 1-2 m wide, but the room is no corridor.
  AreaRaster raster = RasterOf({{0, 0, 160, 120}});
  for (const int x : {20, 70, 120}) raster.labels(cv::Rect(x, 40, 16, 32)).setTo(0);
  // A corridor 2 m wide around a block of rooms 16 x 8 m (other areas).
  cv::Mat& labels = raster.labels;
  labels(cv::Rect(200, 0, 400, 400)).setTo(2);
  labels(cv::Rect(240, 40, 320, 160)).setTo(3);
  labels(cv::Rect(240, 200, 320, 160)).setTo(0);
  raster.cell_count.resize(3);
  CountAreaCells(&raster);
  const AreaShape room = RasterShape(raster, 0, kResolutionM, kIslandMaxM);
  EXPECT_NEAR(room.area_px, 160 * 120, 1);  // the desks count
  EXPECT_NEAR(room.widest_px, 120, 4);
  EXPECT_FALSE(room.corridor);
  const AreaShape loop = RasterShape(raster, 1, kResolutionM, kIslandMaxM);
  EXPECT_NEAR(loop.area_px, 400 * 400 - 320 * 320, 1);  // the block does not
  EXPECT_NEAR(loop.typical_px, 40, 2);
  EXPECT_LT(loop.widest_px, 60);
  EXPECT_TRUE(loop.corridor);
}

TEST(MeasureAreaShapesTest, WidthsFromTheClearanceSizesFromThePolygons) {
  // A room-less edge 200 px long and 20 px wide (a 200 x 20 px polygon)
  // whose clearance swells to 30 px at the junction at its end, within that
  // junction's disk.
  proto::CutGraph graph;
  const int a = AddVertex(&graph, VERTEX_DEAD_END, 10, 0, 0);
  const int b = AddVertex(&graph, VERTEX_JUNCTION, 30, 200, 0);
  AddStraightEdge(&graph, a, b, -1, {0, 0}, {200, 0}, 10, 20, 20, {10, 10, 30});
  const AreaPlan plan = AssignAreas(graph);
  const std::vector<AreaShape> shapes = MeasureAreaShapes(graph, plan, kResolutionM);
  ASSERT_EQ(shapes.size(), 1u);
  EXPECT_EQ(shapes[0].typical_px, 20);
  // The junction's disk is no part of the corridor's width profile.
  EXPECT_EQ(shapes[0].widest_px, 20);
  EXPECT_NEAR(shapes[0].area_px, 4000, 1e-6);
  EXPECT_NEAR(shapes[0].Elongation(), 10, 1e-6);
  EXPECT_TRUE(shapes[0].corridor);
  // Without that disk the swell is the widest, and 4000 px are not 4
  // squares of 60 px.
  graph.mutable_vertices(b)->set_clearance_px(0);
  const std::vector<AreaShape> swollen = MeasureAreaShapes(graph, plan, kResolutionM);
  EXPECT_EQ(swollen[0].widest_px, 60);
  EXPECT_FALSE(swollen[0].corridor);
  EXPECT_GT(shapes[0].Straightness(), 50);
}

TEST(CorridorShapeTest, OneDefinition) {
  // 3 m typical, 4 squares of the widest 3.5 m: 49 m2.
  EXPECT_TRUE(IsCorridorShaped(60, 70, 4 * 70 * 70, kResolutionM));
  EXPECT_FALSE(IsCorridorShaped(60, 70, 4 * 70 * 70 - 1, kResolutionM));
  // Wider than 4 m typically: a hall, however long.
  EXPECT_FALSE(IsCorridorShaped(82, 82, 100 * 82 * 82, kResolutionM));
  EXPECT_FALSE(IsCorridorShaped(0, 0, 100, kResolutionM));
}

// A map 8 x 6 m at 0.05 m/px, free inside a 0.15 m wall one cell in from
// the image border (the walls are the map's typical wall).
proto::CleanedMap WalledMap(const std::vector<cv::Rect>& obstacles) {
  cv::Mat cells(120, 160, CV_8U, cv::Scalar(proto::CELL_FREE));
  std::vector<cv::Rect> walls{{2, 2, 156, 3}, {2, 115, 156, 3}, {2, 2, 3, 116}, {155, 2, 3, 116}};
  walls.insert(walls.end(), obstacles.begin(), obstacles.end());
  for (const cv::Rect& rect : walls) cells(rect).setTo(proto::CELL_OCCUPIED);
  return CleanedMapOfCells(cells);
}

TEST(FurnitureIslandsTest, DesksAreIslandsWallPiecesAndSpecksAreNot) {
  // A desk (1.6 x 0.8 m), a piece of wall (3 m x 0.15 m), a speck (2 cells),
  // a cabinet against the outer wall and a free block 5 m long.
  const cv::Mat islands = FurnitureIslandCells(
      WalledMap(
          {{20, 20, 32, 16}, {80, 20, 60, 3}, {30, 60, 2, 1}, {3, 90, 20, 10}, {20, 104, 100, 10}}),
      kIslandMaxM, /*fill_outlines=*/false, /*max_elongation=*/0);
  EXPECT_EQ(islands.at<uint8_t>(25, 30), 1);
  EXPECT_EQ(islands.at<uint8_t>(21, 100), 0);
  EXPECT_EQ(islands.at<uint8_t>(60, 30), 0);
  EXPECT_EQ(islands.at<uint8_t>(95, 10), 0);  // joined to the wall
  EXPECT_EQ(islands.at<uint8_t>(110, 60), 0);
  EXPECT_EQ(islands.at<uint8_t>(60, 60), 0);  // free space
}

TEST(FurnitureIslandsTest, ADeskDrawnAsAnOutlineIsAnIslandOnceFilled) {
  // A desk 1.6 x 0.8 m drawn as a one-cell outline: a thin ring, no island,
  // unless its inside (no one reaches it) is filled first.
  cv::Mat cells(120, 160, CV_8U, cv::Scalar(proto::CELL_FREE));
  for (const cv::Rect& wall : {cv::Rect(2, 2, 156, 3), cv::Rect(2, 115, 156, 3),
                               cv::Rect(2, 2, 3, 116), cv::Rect(155, 2, 3, 116)}) {
    cells(wall).setTo(proto::CELL_OCCUPIED);
  }
  cv::rectangle(cells, cv::Rect(40, 40, 32, 16), cv::Scalar(proto::CELL_OCCUPIED));
  const proto::CleanedMap map = CleanedMapOfCells(cells);
  EXPECT_EQ(FurnitureIslandCells(map, kIslandMaxM, false, 0).at<uint8_t>(40, 50), 0);
  EXPECT_EQ(FurnitureIslandCells(map, kIslandMaxM, true, 0).at<uint8_t>(40, 50), 1);
}

TEST(FurnitureIslandsTest, WithAnElongationLimitAThickPieceOfWallIsNoIsland) {
  // A piece of wall 2.4 x 0.4 m (6 times as long as wide; lab_d's is 2.5 x
  // 0.3 m) and a desk 1.6 x 0.8 m.
  const proto::CleanedMap map = WalledMap({{20, 20, 48, 8}, {20, 60, 32, 16}});
  const cv::Mat any_shape = FurnitureIslandCells(map, kIslandMaxM, false, 0);
  const cv::Mat limited = FurnitureIslandCells(map, kIslandMaxM, false, 5);
  EXPECT_EQ(any_shape.at<uint8_t>(24, 40), 1);
  EXPECT_EQ(limited.at<uint8_t>(24, 40), 0);
  EXPECT_EQ(any_shape.at<uint8_t>(68, 30), 1);
  EXPECT_EQ(limited.at<uint8_t>(68, 30), 1);
}

}  // namespace
}  // namespace areagraph::testing

namespace areagraph::testing {
namespace {

// Filling every enclosed pocket fills what the outer contours hold.
TEST(FillEnclosedPocketsTest, WithoutALimitSameAsFillingTheOuterContours) {
  std::mt19937 random(12);
  int filled_cells = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const int cols = std::uniform_int_distribution<int>(3, 70)(random);
    const int rows = std::uniform_int_distribution<int>(3, 50)(random);
    cv::Mat inner(rows - 2, cols - 2, CV_8U);
    // Sparse to dense noise, then blobs and rings with gaps.
    const int percent = std::uniform_int_distribution<int>(5, 95)(random);
    cv::randu(inner, 0, 100);
    inner = inner < percent;
    for (int k = 0; k < 3; ++k) {
      const cv::Point centre(std::uniform_int_distribution<int>(0, cols)(random),
                             std::uniform_int_distribution<int>(0, rows)(random));
      const int radius = std::uniform_int_distribution<int>(1, 15)(random);
      cv::circle(inner, centre, radius, cv::Scalar(255),
                 std::uniform_int_distribution<int>(1, 2)(random),
                 k == 0 ? cv::LINE_4 : cv::LINE_8);
    }
    cv::Mat mask = cv::Mat::zeros(rows, cols, CV_8U);
    inner.copyTo(mask(cv::Rect(1, 1, cols - 2, rows - 2)));
    cv::Mat want = mask.clone();
    std::vector<std::vector<cv::Point>> outer;
    cv::findContours(mask.clone(), outer, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
    cv::drawContours(want, outer, -1, cv::Scalar(255), cv::FILLED);
    cv::Mat got = mask.clone();
    FillEnclosedPockets(std::numeric_limits<double>::infinity(), &got);
    ASSERT_EQ(cv::countNonZero(got != want), 0) << "trial " << trial;
    filled_cells += cv::countNonZero(got) - cv::countNonZero(mask);
  }
  EXPECT_GT(filled_cells, 5000);
}

}  // namespace
}  // namespace areagraph::testing
