// PaintPathCells against two cv::polylines calls (LINE_4), as merge's
// partition drew the paths before: the same cells in both images, on random
// paths of short steps (rows, columns, diagonals), long jumps and points
// outside the image.
#include "stages/merge/path_cells.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <random>

namespace areagraph::testing {
namespace {

TEST(PathCells, SameCellsAsPolylines) {
  std::mt19937 random(14);
  auto uniform = [&](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(random);
  };
  int diagonal_steps = 0, outside_points = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int cols = 5 + static_cast<int>(uniform(0, 60)),
              rows = 5 + static_cast<int>(uniform(0, 60));
    cv::Mat labels(rows, cols, CV_32S), marks(rows, cols, CV_8U);
    cv::randu(labels, -3, 9);
    cv::randu(marks, 0, 3);
    cv::Mat want_labels = labels.clone(), want_marks = marks.clone();
    for (int p = 0; p < 6; ++p) {
      PointList path;
      const int points = 1 + static_cast<int>(uniform(0, 25));
      Eigen::Vector2d at(uniform(-4, cols + 4), uniform(-4, rows + 4));
      for (int i = 0; i < points; ++i) {
        path.push_back(at);
        const double kind = uniform(0, 1);
        if (kind < 0.3) {
          at += Eigen::Vector2d(uniform(-1.5, 1.5), uniform(-1.5, 1.5));
        } else if (kind < 0.5) {
          at.x() += uniform(-12, 12);
        } else if (kind < 0.7) {
          at.y() += uniform(-12, 12);
        } else {
          at = Eigen::Vector2d(uniform(-4, cols + 4), uniform(-4, rows + 4));
        }
      }
      std::vector<cv::Point> cells;
      for (const Eigen::Vector2d& q : path) {
        cells.emplace_back(static_cast<int>(std::floor(q.x())),
                           static_cast<int>(std::floor(q.y())));
        outside_points += !cv::Rect(0, 0, cols, rows).contains(cells.back());
      }
      for (size_t i = 1; i < cells.size(); ++i) {
        diagonal_steps += std::abs(cells[i].x - cells[i - 1].x) == 1 &&
                          std::abs(cells[i].y - cells[i - 1].y) == 1;
      }
      const int value = 10 + p;
      cv::polylines(want_labels, cells, false, cv::Scalar(value), 1, cv::LINE_4);
      cv::polylines(want_marks, cells, false, cv::Scalar(1), 1, cv::LINE_4);
      PaintPathCells(path, value, &labels, &marks);
    }
    ASSERT_EQ(cv::countNonZero(labels != want_labels), 0) << "trial " << trial;
    ASSERT_EQ(cv::countNonZero(marks != want_marks), 0) << "trial " << trial;
  }
  // The cases the direct painting leaves to cv::LineIterator occurred.
  EXPECT_GT(diagonal_steps, 50);
  EXPECT_GT(outside_points, 100);
}

}  // namespace
}  // namespace areagraph::testing
