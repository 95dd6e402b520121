// LabelCorridorsByShape and FurnitureIslandCells on drawn rasters.
#include "stages/merge/corridor_labels.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <random>
#include <thread>

#include "proto/pipeline_options.pb.h"
#include "stages/merge/corridor_stem_joining.h"
#include "stages/merge/furniture_gap_joining.h"
#include "tests/stages/merge/hand_made_cut_graph.h"
#include "tests/support/area_test_support.h"
#include "tests/support/thread_count.h"

namespace areagraph::testing {
namespace {

// A raster of rectangles, area k + 1 on rects[k], at 0.05 m/px.
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

AreaPlan RoomsOnly(int count) {
  AreaPlan plan;
  for (int k = 0; k < count; ++k) plan.areas.push_back({AREA_ROOM, k, {k}});
  return plan;
}

TEST(CorridorLabelsTest, LongNarrowRoomBecomesACorridor) {
  // 2 x 10 m, 4 x 5 m with a 1 x 1 m desk in it (a hole), 5 x 25 m (a hall
  // wider than a corridor), and an L of two 1.5 m wide arms 6 m long.
  AreaRaster raster =
      RasterOf({{0, 0, 200, 40}, {0, 50, 100, 80}, {0, 140, 500, 100}, {520, 0, 30, 120}});
  raster.labels(cv::Rect(40, 80, 20, 20)).setTo(0);
  raster.labels(cv::Rect(430, 90, 90, 30)).setTo(4);
  CountAreaCells(&raster);
  AreaPlan plan = RoomsOnly(4);
  LabelCorridorsByShape(raster, 0.05, &plan);
  EXPECT_EQ(plan.areas[0].kind, AREA_CORRIDOR);
  EXPECT_EQ(plan.areas[1].kind, AREA_ROOM);
  EXPECT_EQ(plan.areas[2].kind, AREA_ROOM);
  EXPECT_EQ(plan.areas[3].kind, AREA_CORRIDOR);
}

TEST(CorridorLabelsTest, DeadEndsKeepTheirKind) {
  AreaRaster raster = RasterOf({{0, 0, 200, 40}});
  AreaPlan plan = RoomsOnly(1);
  plan.areas[0].kind = AREA_DEAD_END;
  LabelCorridorsByShape(raster, 0.05, &plan);
  EXPECT_EQ(plan.areas[0].kind, AREA_DEAD_END);
}

// 60 random rectangles, some long and narrow (corridors by shape), some
// squarer, with a few dead ends among them.
std::pair<AreaRaster, AreaPlan> RandomRooms(unsigned seed) {
  std::mt19937 random(seed);
  std::vector<cv::Rect> rects;
  for (int k = 0; k < 60; ++k) {
    const int x = static_cast<int>(random() % 10) * 60, y = static_cast<int>(random() % 8) * 50;
    const bool narrow = random() % 2 == 0;
    rects.emplace_back(x, y, narrow ? 55 : 30 + static_cast<int>(random() % 25),
                       narrow ? 8 + static_cast<int>(random() % 6) : 45);
  }
  AreaPlan plan = RoomsOnly(static_cast<int>(rects.size()));
  for (int k = 0; k < 60; k += 7) plan.areas[k].kind = AREA_DEAD_END;
  return {RasterOf(rects), plan};
}

std::vector<proto::AreaKind> KindsOf(const AreaPlan& plan) {
  std::vector<proto::AreaKind> kinds;
  for (const AreaPlan::Area& area : plan.areas) kinds.push_back(area.kind);
  return kinds;
}

TEST(CorridorShapeWorkTest, SharedByThreadsGivesLabelCorridorsByShapesKinds) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const auto [raster, plan] = RandomRooms(seed);
    AreaPlan expected = plan;
    {
      ThreadCount one(1);
      LabelCorridorsByShape(raster, 0.05, &expected);
    }
    const std::vector<proto::AreaKind> before = KindsOf(plan), after = KindsOf(expected);
    ASSERT_GT(std::count(after.begin(), after.end(), AREA_CORRIDOR), 3) << seed;
    ASSERT_NE(before, after) << seed;
    // Finish alone measures every room.
    AreaPlan alone = plan;
    CorridorShapeWork alone_work(raster, 0.05, alone);
    alone_work.Finish();
    alone_work.Apply(&alone);
    EXPECT_EQ(KindsOf(alone), after) << seed;
    // Two threads measuring while Finish takes the rest.
    AreaPlan shared = plan;
    CorridorShapeWork work(raster, 0.05, shared);
    std::thread first([&] { work.Measure(); }), second([&] { work.Measure(); });
    work.Finish();
    work.Apply(&shared);
    first.join();
    second.join();
    EXPECT_EQ(KindsOf(shared), after) << seed;
  }
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
      /*fill_pockets_m=*/0, /*against_walls=*/false, /*max_elongation=*/0);
  EXPECT_EQ(islands.at<uint8_t>(25, 30), 1);
  EXPECT_EQ(islands.at<uint8_t>(21, 100), 0);
  EXPECT_EQ(islands.at<uint8_t>(60, 30), 0);
  EXPECT_EQ(islands.at<uint8_t>(95, 10), 0);  // joined to the wall
  EXPECT_EQ(islands.at<uint8_t>(110, 60), 0);
  EXPECT_EQ(islands.at<uint8_t>(60, 60), 0);  // free space
}

TEST(FurnitureIslandsTest, WithAnElongationLimitAThickPieceOfWallIsNoIsland) {
  // A piece of wall 2.4 x 0.4 m (6 times as long as wide; lab_d's is 2.5 x
  // 0.3 m) and a desk 1.6 x 0.8 m.
  const proto::CleanedMap map = WalledMap({{20, 20, 48, 8}, {20, 60, 32, 16}});
  const cv::Mat any_shape = FurnitureIslandCells(map, 0, /*against_walls=*/false, 0);
  const cv::Mat limited = FurnitureIslandCells(map, 0, /*against_walls=*/false, 5);
  EXPECT_EQ(any_shape.at<uint8_t>(24, 40), 1);
  EXPECT_EQ(limited.at<uint8_t>(24, 40), 0);
  EXPECT_EQ(any_shape.at<uint8_t>(68, 30), 1);
  EXPECT_EQ(limited.at<uint8_t>(68, 30), 1);
}

TEST(FurnitureIslandsTest, WithAgainstWallsACabinetByAThinWallIsAnIsland) {
  // The cabinet (1 x 0.5 m) against the outer wall, a desk, a piece of
  // wall with a 0.5 x 0.5 m cabinet at its end, and a 0.5 m thick piece
  // of wall 5 m long against the outer wall.
  const proto::CleanedMap map = WalledMap(
      {{3, 90, 20, 10}, {20, 20, 32, 16}, {80, 20, 60, 3}, {80, 23, 10, 10}, {60, 5, 10, 100}});
  const cv::Mat without = FurnitureIslandCells(map, 0, /*against_walls=*/false, 0);
  const cv::Mat with = FurnitureIslandCells(map, 0, /*against_walls=*/true, 0);
  EXPECT_EQ(without.at<uint8_t>(95, 10), 0);
  EXPECT_EQ(with.at<uint8_t>(95, 10), 2);  // the cabinet, an island against a wall
  EXPECT_EQ(with.at<uint8_t>(3, 10), 0);   // the outer wall behind it
  EXPECT_EQ(with.at<uint8_t>(25, 30), 1);  // the desk, either way
  EXPECT_EQ(without.at<uint8_t>(28, 85), 0);
  EXPECT_EQ(with.at<uint8_t>(28, 85), 2);   // the cabinet at the wall's end
  EXPECT_EQ(with.at<uint8_t>(21, 120), 0);  // the wall piece itself
  EXPECT_EQ(with.at<uint8_t>(50, 65), 0);   // the thick wall is too long
}

// Stem joining stops at halls by the same limit that tells corridors from
// halls by shape, in the options and in the function's own default.
TEST(CorridorStemsTest, TheWidthLimitIsTheCorridorWidthLimit) {
  EXPECT_EQ(proto::MergeOptions().corridor_stems_max_width_m(), kMaxCorridorWidthM);
  EXPECT_EQ(CorridorStemParams().max_corridor_width_m, kMaxCorridorWidthM);
}

}  // namespace
}  // namespace areagraph::testing

namespace areagraph::testing {
namespace {

// FillHoles against what merge did before: fill the outer contours.
TEST(FillHoles, SameAsFillingTheOuterContours) {
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
    FillHoles(&got);
    ASSERT_EQ(cv::countNonZero(got != want), 0) << "trial " << trial;
    filled_cells += cv::countNonZero(got) - cv::countNonZero(mask);
  }
  EXPECT_GT(filled_cells, 5000);
}

}  // namespace
}  // namespace areagraph::testing
