// FurnitureIslandsAt, which walks only the regions around the cells asked,
// against a whole-map reference: every region labelled by OpenCV, measured
// by OpenCV's distance transform, and tested by the same rules.
#include "stages/merge/furniture_islands.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <random>

#include "stages/geometry/wall_thickness.h"
#include "tests/support/area_test_support.h"

namespace areagraph::testing {
namespace {

constexpr double kResolutionM = 0.05;
// cut.islands.max_length_m's default, which the CutGraph carries to merge.
constexpr double kIslandMaxM = 4.0;

// Walls round a 220 x 170 map, thin inner walls, and blocks of every size:
// desks, specks, long pieces of wall, blocks against walls and touching
// each other.
proto::CleanedMap ClutteredMap(unsigned seed) {
  cv::Mat cells(170, 220, CV_8U, cv::Scalar(proto::CELL_FREE));
  std::vector<cv::Rect> walls{{0, 0, 220, 3},   {0, 167, 220, 3}, {0, 0, 3, 170},
                              {217, 0, 3, 170}, {100, 3, 2, 80},  {3, 120, 150, 2}};
  std::mt19937 random(seed);
  auto uniform = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(random); };
  for (int k = 0; k < 45; ++k) {
    walls.emplace_back(uniform(4, 200), uniform(4, 150), uniform(1, 60), uniform(1, 20));
  }
  for (const cv::Rect& rect : walls) {
    cells(rect & cv::Rect(0, 0, cells.cols, cells.rows)).setTo(proto::CELL_OCCUPIED);
  }
  for (int k = 0; k < 6; ++k) {
    cv::ellipse(cells, cv::Point(uniform(20, 200), uniform(20, 150)),
                cv::Size(uniform(3, 12), uniform(3, 12)), uniform(0, 90), 0, 360,
                cv::Scalar(proto::CELL_UNKNOWN), cv::FILLED);
  }
  return CleanedMapOfCells(cells, kResolutionM);
}

// Marks `value` where it is 0 on the islands of `mask`, the whole map at once.
void MarkReference(const cv::Mat& mask, const cv::Mat& depth, double min_thickness_px,
                   double max_elongation, uint8_t value, cv::Mat* out) {
  cv::Mat labels, stats, centroids;
  const int count = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S);
  const double max_px = kIslandMaxM / kResolutionM;
  for (int k = 1; k < count; ++k) {
    const cv::Rect box(stats.at<int>(k, cv::CC_STAT_LEFT), stats.at<int>(k, cv::CC_STAT_TOP),
                       stats.at<int>(k, cv::CC_STAT_WIDTH), stats.at<int>(k, cv::CC_STAT_HEIGHT));
    if (box.x == 0 || box.y == 0 || box.br().x == mask.cols || box.br().y == mask.rows) continue;
    if (std::max(box.width, box.height) > max_px) continue;
    std::vector<cv::Point> points;
    float deepest = 0;
    for (int r = box.y; r < box.br().y; ++r) {
      for (int c = box.x; c < box.br().x; ++c) {
        if (labels.at<int>(r, c) != k) continue;
        points.emplace_back(c, r);
        deepest = std::max(deepest, depth.at<float>(r, c));
      }
    }
    if (2 * deepest < min_thickness_px) continue;
    const cv::RotatedRect rect = cv::minAreaRect(points);
    if (stats.at<int>(k, cv::CC_STAT_AREA) <
        kMinFurnitureSolidity * (rect.size.width + 1) * (rect.size.height + 1)) {
      continue;
    }
    const double longer = std::max(rect.size.width, rect.size.height) + 1;
    const double shorter = std::min(rect.size.width, rect.size.height) + 1;
    if (max_elongation > 0 && longer > max_elongation * shorter) continue;
    for (const cv::Point& p : points) {
      if (out->at<uint8_t>(p) == 0) out->at<uint8_t>(p) = value;
    }
  }
}

cv::Mat ReferenceIslands(const proto::CleanedMap& map, double max_elongation) {
  const cv::Mat cells(map.frame().height_px(), map.frame().width_px(), CV_8U,
                      const_cast<char*>(map.cells().data()));
  const cv::Mat obstacle = cells != proto::CELL_FREE;
  cv::Mat depth;
  cv::distanceTransform(obstacle, depth, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  const double min_thickness_px = std::max(
      kMinFurnitureThicknessM / kResolutionM,
      kFurnitureWallRatio * TypicalWallThickness(depth, kMaxWallThicknessM / kResolutionM));
  cv::Mat out = cv::Mat::zeros(cells.size(), CV_8U);
  MarkReference(obstacle, depth, min_thickness_px, max_elongation, 1, &out);
  return out;
}

TEST(FurnitureIslandsTest, EveryCellAsTheWholeMapReferenceHasIt) {
  int islands = 0;
  for (unsigned seed = 1; seed <= 6; ++seed) {
    const proto::CleanedMap map = ClutteredMap(seed);
    for (const double elongation : {0.0, 5.0}) {
      const cv::Mat expected = ReferenceIslands(map, elongation);
      const cv::Mat all = FurnitureIslandCells(map, kIslandMaxM, false, elongation);
      ASSERT_EQ(cv::countNonZero(all != expected), 0) << seed << " " << elongation;
      islands += cv::countNonZero(expected == 1);
      // A few cells asked in a random order, some outside the map: the
      // walks of earlier cells must not change later answers.
      // Most of them on obstacles.
      std::mt19937 random(seed);
      std::vector<cv::Point> cells;
      for (int r = 0; r < expected.rows; ++r) {
        for (int c = 0; c < expected.cols; ++c) {
          if (map.cells()[r * expected.cols + c] != proto::CELL_FREE) cells.emplace_back(c, r);
        }
      }
      std::shuffle(cells.begin(), cells.end(), random);
      cells.resize(300);
      for (int k = 0; k < 100; ++k) {
        cells.emplace_back(std::uniform_int_distribution<int>(-2, expected.cols + 1)(random),
                           std::uniform_int_distribution<int>(-2, expected.rows + 1)(random));
      }
      const std::vector<uint8_t> values =
          FurnitureIslandsAt(map, kIslandMaxM, false, elongation, cells);
      for (size_t i = 0; i < cells.size(); ++i) {
        const bool inside = cv::Rect(0, 0, expected.cols, expected.rows).contains(cells[i]);
        EXPECT_EQ(values[i], inside ? expected.at<uint8_t>(cells[i]) : 0) << cells[i];
      }
    }
  }
  EXPECT_GT(islands, 0);
}

}  // namespace
}  // namespace areagraph::testing
