#include "stages/geometry/distance_transform.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <opencv2/imgproc.hpp>
#include <random>
#include <vector>

#include "tests/support/thread_count.h"

namespace areagraph {
namespace {

using areagraph::testing::ThreadCount;

cv::Mat OpenCvDistances(const cv::Mat& mask) {
  cv::Mat distance;
  cv::distanceTransform(mask, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  return distance;
}

// Bit for bit: the stages' outputs must not move when they switch.
void ExpectSameAsOpenCv(const cv::Mat& mask) {
  const cv::Mat expected = OpenCvDistances(mask);
  const cv::Mat actual = ExactDistanceTransform(mask);
  ASSERT_EQ(actual.type(), CV_32F);
  ASSERT_EQ(actual.size(), mask.size());
  for (int r = 0; r < mask.rows; ++r) {
    ASSERT_EQ(std::memcmp(actual.ptr(r), expected.ptr(r), sizeof(float) * mask.cols), 0)
        << "row " << r << " of " << mask.cols << " x " << mask.rows;
  }
  double deepest = 0;
  cv::minMaxLoc(expected, nullptr, &deepest);
  EXPECT_EQ(DeepestDistance(mask), deepest);
  // Per 8-connected region of the non-zero cells (label 0: the zero cells).
  cv::Mat labels;
  const int count = cv::connectedComponents(mask, labels, 8, CV_32S);
  std::vector<float> expected_deepest(count, 0);
  for (int r = 0; r < mask.rows; ++r) {
    for (int c = 0; c < mask.cols; ++c) {
      float& d = expected_deepest[labels.at<int>(r, c)];
      d = std::max(d, expected.at<float>(r, c));
    }
  }
  EXPECT_EQ(DeepestPerLabel(mask, labels, count), expected_deepest);
  EXPECT_EQ(DeepestPerLabel(mask, labels, count, expected), expected_deepest);
  // The same regions as runs, the labels of every other row left out (their
  // rows only pass the column distances on).
  std::vector<PieceRun> runs;
  std::vector<float> expected_of_runs(count, 0);
  for (int r = 0; r < mask.rows; r += 2) {
    for (int c = 0; c < mask.cols; ++c) {
      const int label = labels.at<int>(r, c);
      if (label == 0) continue;
      if (!runs.empty() && runs.back().row == r && runs.back().end == c &&
          runs.back().value == label) {
        ++runs.back().end;
      } else {
        runs.push_back({r, c, c + 1, label});
      }
      expected_of_runs[label] = std::max(expected_of_runs[label], expected.at<float>(r, c));
    }
  }
  EXPECT_EQ(DeepestPerRun(mask, runs, count), expected_of_runs);
}

// DistanceAtLeast(mask, reach) is OpenCV's distances thresholded at `reach`.
void ExpectThresholdedOpenCv(const cv::Mat& mask, const cv::Mat& distance, float reach) {
  const cv::Mat at_least = DistanceAtLeast(mask, reach);
  ASSERT_EQ(at_least.type(), CV_8U);
  for (int r = 0; r < mask.rows; ++r) {
    for (int c = 0; c < mask.cols; ++c) {
      ASSERT_EQ(at_least.at<uint8_t>(r, c), distance.at<float>(r, c) >= reach ? 1 : 0)
          << "reach " << reach << " at " << c << "," << r << " of " << mask.cols << " x "
          << mask.rows;
    }
  }
}

// Zero cells with probability `zero_share`, else 255.
cv::Mat RandomMask(std::mt19937& random, int rows, int cols, double zero_share) {
  cv::Mat mask(rows, cols, CV_8U);
  std::bernoulli_distribution zero(zero_share);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) mask.at<uint8_t>(r, c) = zero(random) ? 0 : 255;
  }
  return mask;
}

// A map-like mask: walls (0) of 1-4 cells around rectangular rooms, some
// boxes of furniture, the rest 255; `invert` swaps them (walls non-zero).
cv::Mat RoomsMask(std::mt19937& random, int rows, int cols, bool invert) {
  cv::Mat mask(rows, cols, CV_8U, cv::Scalar(255));
  std::uniform_int_distribution<int> x(0, cols - 1), y(0, rows - 1), thick(1, 4);
  for (int wall = 0; wall < 30; ++wall) {
    const cv::Point a(x(random), y(random));
    const cv::Point b = random() % 2 ? cv::Point(x(random), a.y) : cv::Point(a.x, y(random));
    cv::line(mask, a, b, cv::Scalar(0), thick(random));
  }
  for (int box = 0; box < 10; ++box) {
    const cv::Point a(x(random), y(random));
    cv::rectangle(mask, a, a + cv::Point(thick(random) * 3, thick(random) * 2), cv::Scalar(0),
                  cv::FILLED);
  }
  if (invert) cv::bitwise_not(mask, mask);
  return mask;
}

TEST(ExactDistanceTransform, EqualsOpenCvOnRandomMasks) {
  std::mt19937 random(14);
  for (int trial = 0; trial < 60; ++trial) {
    const int rows = 1 + int(random() % 90), cols = 1 + int(random() % 90);
    const double shares[] = {0.002, 0.02, 0.2, 0.5, 0.9};
    ExpectSameAsOpenCv(RandomMask(random, rows, cols, shares[trial % 5]));
  }
}

TEST(ExactDistanceTransform, EqualsOpenCvOnLargeSparseMasks) {
  // Few zero cells far apart: long rows of parabolas, breakpoints far from
  // the cells, distances in the hundreds.
  std::mt19937 random(3);
  for (const double share : {0.00001, 0.0001, 0.001}) {
    ExpectSameAsOpenCv(RandomMask(random, 700, 1300, share));
  }
}

TEST(ExactDistanceTransform, EqualsOpenCvOnMapLikeMasks) {
  std::mt19937 random(5);
  for (int trial = 0; trial < 6; ++trial) {
    const bool invert = trial % 2 == 1;
    ExpectSameAsOpenCv(RoomsMask(random, 400 + 100 * trial, 900 - 50 * trial, invert));
  }
}

TEST(ExactDistanceTransform, KnownDistancesAroundOneZeroCell) {
  cv::Mat mask(41, 57, CV_8U, cv::Scalar(255));
  mask.at<uint8_t>(13, 29) = 0;
  const cv::Mat distance = ExactDistanceTransform(mask);
  for (int r = 0; r < mask.rows; ++r) {
    for (int c = 0; c < mask.cols; ++c) {
      const float expected = std::sqrt(float((r - 13) * (r - 13) + (c - 29) * (c - 29)));
      ASSERT_EQ(distance.at<float>(r, c), expected) << c << "," << r;
    }
  }
  EXPECT_EQ(DeepestDistance(mask), std::sqrt(float(27 * 27 + 29 * 29)));
}

TEST(ExactDistanceTransform, ZerosOnlyOnTheEdgesAndThinMasks) {
  // Columns without a zero cell, zero cells only on one border, one row,
  // one column, a single cell.
  cv::Mat left(30, 50, CV_8U, cv::Scalar(255));
  left.col(0).setTo(0);
  ExpectSameAsOpenCv(left);
  cv::Mat bottom(30, 50, CV_8U, cv::Scalar(255));
  bottom.row(29).setTo(0);
  ExpectSameAsOpenCv(bottom);
  cv::Mat corner(30, 50, CV_8U, cv::Scalar(255));
  corner.at<uint8_t>(29, 49) = 0;
  ExpectSameAsOpenCv(corner);
  std::mt19937 random(8);
  ExpectSameAsOpenCv(RandomMask(random, 1, 200, 0.05));
  ExpectSameAsOpenCv(RandomMask(random, 200, 1, 0.05));
  ExpectSameAsOpenCv(cv::Mat(1, 1, CV_8U, cv::Scalar(0)));
}

// Over 4096 cells wide OpenCV's single-precision arithmetic is not exact; the
// transform must then give OpenCV's rounding, not the true distances.
TEST(ExactDistanceTransform, EqualsOpenCvOnMasksOver4096Wide) {
  std::mt19937 random(14);
  const double shares[] = {0.5, 0.02, 0.001, 0.0002};
  for (int trial = 0; trial < 4; ++trial) {
    ExpectSameAsOpenCv(RandomMask(random, 40 + 90 * trial, 4100 + 400 * trial, shares[trial]));
  }
  for (const bool invert : {false, true}) {
    ExpectSameAsOpenCv(RoomsMask(random, 300, 5200, invert));
    ExpectSameAsOpenCv(RoomsMask(random, 4700, 120, invert));
  }
  // Columns without any zero cell beside far zero cells.
  cv::Mat sparse(200, 5000, CV_8U, cv::Scalar(255));
  sparse.at<uint8_t>(199, 4999) = 0;
  sparse.at<uint8_t>(0, 7) = 0;
  sparse.at<uint8_t>(100, 2600) = 0;
  ExpectSameAsOpenCv(sparse);
  ExpectSameAsOpenCv(cv::Mat(30, 4500, CV_8U, cv::Scalar(255)));
}

// Around the width where the row alone leaves the exact transform (4097
// cells: 4096^2 = 2^24), with columns both near and far from a zero cell.
TEST(ExactDistanceTransform, EqualsOpenCvAtTheWidthWhereTheExactTransformStops) {
  std::mt19937 random(4097);
  for (const int cols : {4095, 4096, 4097, 4098}) {
    ExpectSameAsOpenCv(RandomMask(random, 60, cols, 0.001));
    cv::Mat two_zeros(50, cols, CV_8U, cv::Scalar(255));
    two_zeros.at<uint8_t>(0, 0) = 0;
    two_zeros.at<uint8_t>(49, cols - 1) = 0;
    ExpectSameAsOpenCv(two_zeros);
  }
}

TEST(DistanceAtLeast, EqualsThresholdedOpenCvDistancesOver4096Wide) {
  std::mt19937 random(41);
  const cv::Mat mask = RoomsMask(random, 200, 4800, false);
  const cv::Mat distance = OpenCvDistances(mask);
  for (const float reach : {0.5f, 3.0f, 7.3f}) ExpectThresholdedOpenCv(mask, distance, reach);
}

// Reaches at OpenCV's own distances and one float either side of them: the
// threshold on squares beyond 4097 cells across must cut exactly there.
TEST(DistanceAtLeast, EqualsThresholdedOpenCvDistancesAtTheirOwnValues) {
  std::mt19937 random(43);
  const cv::Mat mask = RoomsMask(random, 120, 5200, false);
  const cv::Mat distance = OpenCvDistances(mask);
  for (const float d : {1.0f, 1.4142135f, 2.236068f, 5.0f, 7.0710678f}) {
    for (const float reach : {std::nextafter(d, 0.f), d, std::nextafter(d, 100.f)}) {
      ExpectThresholdedOpenCv(mask, distance, reach);
    }
  }
  double deepest = 0;
  cv::minMaxLoc(distance, nullptr, &deepest);
  ExpectThresholdedOpenCv(mask, distance, float(deepest));
  ExpectThresholdedOpenCv(mask, distance, std::nextafter(float(deepest), 1e9f));
}

// Beyond 4097 cells across DistanceAtLeast takes OpenCV's rounding: columns
// without any zero cell, and a mask without any.
TEST(DistanceAtLeast, EqualsThresholdedOpenCvDistancesOver4096WideWithEmptyColumns) {
  cv::Mat one_zero(40, 4500, CV_8U, cv::Scalar(255));
  one_zero.at<uint8_t>(39, 4321) = 0;
  for (const cv::Mat& mask : {one_zero, cv::Mat(20, 4200, CV_8U, cv::Scalar(255))}) {
    const cv::Mat distance = OpenCvDistances(mask);
    for (const float reach : {1.0f, 100.5f, 4000.0f}) {
      ExpectThresholdedOpenCv(mask, distance, reach);
    }
  }
}

TEST(ExactDistanceTransform, MaskWithoutNonZeroCellsIsAllZero) {
  const cv::Mat mask(20, 30, CV_8U, cv::Scalar(0));
  EXPECT_EQ(cv::countNonZero(ExactDistanceTransform(mask)), 0);
  EXPECT_EQ(DeepestDistance(mask), 0);
  EXPECT_EQ(cv::countNonZero(DistanceAtLeast(mask, 0.5f)), 0);
  EXPECT_EQ(cv::countNonZero(DistanceAtLeast(mask, 0.0f)), 20 * 30);
}

TEST(ExactDistanceTransform, MaskWithoutZeroCellsIsOpenCvs) {
  // No zero cell at all: OpenCV's stand-in for infinity, as it gives it.
  const cv::Mat mask(20, 30, CV_8U, cv::Scalar(255));
  ExpectSameAsOpenCv(mask);
  EXPECT_EQ(cv::countNonZero(DistanceAtLeast(mask, 1000.0f)), 20 * 30);
  EXPECT_EQ(ExactDistanceTransform(cv::Mat(0, 0, CV_8U)).total(), 0u);
  EXPECT_EQ(DeepestDistance(cv::Mat(0, 0, CV_8U)), 0);
}

TEST(DistanceAtLeast, EqualsThresholdedOpenCvDistances) {
  std::mt19937 random(21);
  // Whole, half and odd reaches, and ones just beside a square root.
  const float reaches[] = {0.5f,
                           1.0f,
                           std::sqrt(2.0f),
                           std::nextafter(std::sqrt(2.0f), 0.0f),
                           2.5f,
                           3.0f,
                           5.0f,
                           std::sqrt(50.0f),
                           12.25f};
  for (int trial = 0; trial < 24; ++trial) {
    const cv::Mat mask = trial % 3 == 0 ? RoomsMask(random, 200, 300, trial % 2 == 1)
                                        : RandomMask(random, 80, 120, trial % 2 ? 0.01 : 0.1);
    const cv::Mat distance = OpenCvDistances(mask);
    for (const float reach : reaches) ExpectThresholdedOpenCv(mask, distance, reach);
  }
}

TEST(DeepestDistance, EqualsOpenCvsMaximumOnShapes) {
  // Shapes with holes and margins, as merge measures its areas.
  std::mt19937 random(2);
  for (int trial = 0; trial < 30; ++trial) {
    const int rows = 20 + int(random() % 200), cols = 20 + int(random() % 200);
    cv::Mat mask(rows, cols, CV_8U, cv::Scalar(0));
    const int shapes = 1 + int(random() % 4);
    for (int s = 0; s < shapes; ++s) {
      const cv::Point a(1 + int(random() % (cols - 2)), 1 + int(random() % (rows - 2)));
      const cv::Point b(1 + int(random() % (cols - 2)), 1 + int(random() % (rows - 2)));
      if (s % 2 == 0) {
        cv::rectangle(mask, a, b, cv::Scalar(255), cv::FILLED);
      } else {
        cv::circle(mask, a, 1 + int(random() % 40), cv::Scalar(255), cv::FILLED);
      }
    }
    cv::rectangle(mask, cv::Rect(0, 0, cols, rows), cv::Scalar(0));
    double deepest = 0;
    cv::minMaxLoc(OpenCvDistances(mask), nullptr, &deepest);
    ASSERT_EQ(DeepestDistance(mask), deepest) << trial;
  }
}

// The rows (and the columns' passes) go in parallel ranges of at least 2^16
// cells: masks of several such ranges, exact and in OpenCV's rounding, give
// OpenCV's values on one, two and three threads.
TEST(ExactDistanceTransform, EqualsOpenCvOnOneTwoAndThreeThreads) {
  std::mt19937 random(1414);
  const cv::Mat wide = RoomsMask(random, 240, 4700, false);
  const cv::Mat wide_distance = OpenCvDistances(wide);
  const cv::Mat exact = RoomsMask(random, 900, 1000, true);
  const cv::Mat exact_distance = OpenCvDistances(exact);
  for (const int threads : {1, 2, 3}) {
    SCOPED_TRACE(threads);
    ThreadCount count(threads);
    ExpectSameAsOpenCv(wide);
    ExpectSameAsOpenCv(exact);
    for (const float reach : {1.0f, 4.5f}) {
      ExpectThresholdedOpenCv(wide, wide_distance, reach);
      ExpectThresholdedOpenCv(exact, exact_distance, reach);
    }
  }
}

}  // namespace
}  // namespace areagraph
