// CoreCells against DistanceAtLeast on the free cells, masked by the domain
// (what merge's partition computed before): random maps of walls, blocks and
// unknown space, reaches from half a cell to past the byte-sized cap, and
// the maps it leaves to DistanceAtLeast (no obstacle, beyond the exact
// transform).
#include "stages/merge/core_cells.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <random>

#include "stages/geometry/distance_transform.h"
#include "tests/support/area_test_support.h"

namespace areagraph::testing {
namespace {

cv::Mat RandomCells(cv::Size size, std::mt19937& random) {
  auto uniform = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(random); };
  cv::Mat cells(size, CV_8U, cv::Scalar(proto::CELL_FREE));
  for (int k = 0; k < uniform(0, 40); ++k) {
    const cv::Rect rect(uniform(-5, size.width), uniform(-5, size.height), uniform(1, 40),
                        uniform(1, 12));
    const int kind = uniform(0, 2);
    cells(rect & cv::Rect(cv::Point(), size))
        .setTo(kind == 0 ? proto::CELL_UNKNOWN : proto::CELL_OCCUPIED);
  }
  for (int k = 0; k < uniform(0, 60); ++k) {
    cells.at<uint8_t>(uniform(0, size.height - 1), uniform(0, size.width - 1)) =
        proto::CELL_OCCUPIED;
  }
  return cells;
}

cv::Mat Reference(const cv::Mat& cells, const cv::Mat& domain, double min_gap_px) {
  const cv::Mat free = cells == proto::CELL_FREE;
  cv::Mat core = DistanceAtLeast(free, static_cast<float>(0.5 * min_gap_px));
  core.setTo(0, domain == 0);
  return core;
}

void ExpectSame(const cv::Mat& cells, const cv::Mat& domain, double min_gap_px) {
  const proto::CleanedMap map = CleanedMapOfCells(cells);
  const cv::Mat got = CoreCells(CellGrid(map), domain, min_gap_px);
  const cv::Mat want = Reference(cells, domain, min_gap_px);
  ASSERT_EQ(got.type(), CV_8U);
  ASSERT_EQ(cv::countNonZero(got != want), 0)
      << cells.cols << " x " << cells.rows << ", gap " << min_gap_px;
}

TEST(CoreCells, SameAsDistanceAtLeastOnTheFreeCells) {
  std::mt19937 random(1414);
  const double gaps[] = {0.7, 1, 2, 3.3, 5, 9.99, 10, 17, 40, 120, 499, 520};
  int cores = 0;
  for (int trial = 0; trial < 120; ++trial) {
    const cv::Size size(std::uniform_int_distribution<int>(1, 140)(random),
                        std::uniform_int_distribution<int>(1, 90)(random));
    const cv::Mat cells = RandomCells(size, random);
    cv::Mat domain(size, CV_8U);
    cv::randu(domain, 0, 8);  // about one cell in eight left out
    for (const double gap : gaps) {
      ExpectSame(cells, domain, gap);
      if (gap == 10) {
        cores += cv::countNonZero(CoreCells(CellGrid(CleanedMapOfCells(cells)), domain, gap));
      }
    }
  }
  EXPECT_GT(cores, 10000);
}

TEST(CoreCells, MapsLeftToDistanceAtLeast) {
  std::mt19937 random(7);
  // No obstacle at all: OpenCV's transform, not the exact one.
  const cv::Mat open(30, 50, CV_8U, cv::Scalar(proto::CELL_FREE));
  const cv::Mat domain(open.size(), CV_8U, cv::Scalar(1));
  ExpectSame(open, domain, 10);
  // Wider than the exact transform (4097 + cells): OpenCV's rounding.
  const cv::Mat wide = RandomCells(cv::Size(4300, 12), random);
  ExpectSame(wide, cv::Mat(wide.size(), CV_8U, cv::Scalar(1)), 10);
}

}  // namespace
}  // namespace areagraph::testing
