#include "stages/geometry/region_boxes.h"

#include <gtest/gtest.h>

#include <deque>
#include <opencv2/imgproc.hpp>
#include <random>

namespace areagraph {
namespace {

// Holds LabelRegionsWithBoxes to cv::connectedComponentsWithStats, the
// library call it replaces: the same labels cell for cell and the same five
// statistics for every label that has cells.
void ExpectSameAsOpenCv(const cv::Mat& mask, int connectivity) {
  cv::Mat labels, stats;
  const int count = LabelRegionsWithBoxes(mask, connectivity, &labels, &stats);
  cv::Mat want_labels, want_stats, centroids;
  const int want_count = cv::connectedComponentsWithStats(mask, want_labels, want_stats, centroids,
                                                          connectivity, CV_32S);
  ASSERT_EQ(count, want_count);
  ASSERT_EQ(labels.type(), CV_32S);
  ASSERT_EQ(cv::countNonZero(labels != want_labels), 0);
  ASSERT_EQ(stats.rows, count);
  ASSERT_EQ(stats.type(), CV_32S);
  for (int label = 0; label < count; ++label) {
    if (want_stats.at<int>(label, cv::CC_STAT_AREA) == 0) {
      EXPECT_EQ(stats.at<int>(label, cv::CC_STAT_AREA), 0);
      continue;
    }
    for (int column = 0; column < cv::CC_STAT_MAX; ++column) {
      EXPECT_EQ(stats.at<int>(label, column), want_stats.at<int>(label, column))
          << "label " << label << " column " << column;
    }
  }
}

cv::Mat RandomMask(std::mt19937& random, int rows, int cols, double density) {
  cv::Mat mask(rows, cols, CV_8U);
  std::bernoulli_distribution set(density);
  for (int i = 0; i < rows * cols; ++i) mask.data[i] = set(random) ? 255 : 0;
  return mask;
}

TEST(RegionBoxes, EqualOpenCvsStatisticsOnRandomMasks) {
  std::mt19937 random(14);
  for (const double density : {0.05, 0.3, 0.5, 0.7, 0.95}) {
    for (const cv::Size size :
         {cv::Size(1, 1), cv::Size(1, 37), cv::Size(53, 1), cv::Size(64, 48), cv::Size(301, 177)}) {
      const cv::Mat mask = RandomMask(random, size.height, size.width, density);
      ExpectSameAsOpenCv(mask, 8);
      ExpectSameAsOpenCv(mask, 4);
    }
  }
}

TEST(RegionBoxes, EqualOpenCvsStatisticsOnAMapLikeMask) {
  // Walls around and across, a room with desks, a diagonal wall, an island
  // touching the border, and a large unknown outside.
  cv::Mat mask(400, 600, CV_8U, cv::Scalar(255));
  mask(cv::Rect(40, 30, 500, 330)).setTo(0);
  cv::rectangle(mask, cv::Rect(40, 30, 500, 330), cv::Scalar(255), 3);
  cv::line(mask, {290, 30}, {290, 200}, cv::Scalar(255), 4);
  cv::line(mask, {100, 360}, {400, 120}, cv::Scalar(255), 2);
  for (int k = 0; k < 12; ++k) {
    cv::rectangle(mask, cv::Rect(60 + 35 * k, 250 + (k % 3) * 20, 20, 10), cv::Scalar(255),
                  cv::FILLED);
  }
  cv::circle(mask, {599, 0}, 30, cv::Scalar(0), cv::FILLED);
  ExpectSameAsOpenCv(mask, 8);
  ExpectSameAsOpenCv(mask, 4);
  ExpectSameAsOpenCv(~mask, 8);
  ExpectSameAsOpenCv(~mask, 4);
}

TEST(RegionBoxes, AMaskWithoutBackground) {
  const cv::Mat mask(20, 30, CV_8U, cv::Scalar(255));
  cv::Mat labels, stats;
  ASSERT_EQ(LabelRegionsWithBoxes(mask, 8, &labels, &stats), 2);
  EXPECT_EQ(stats.at<int>(0, cv::CC_STAT_AREA), 0);
  EXPECT_EQ(stats.at<int>(1, cv::CC_STAT_LEFT), 0);
  EXPECT_EQ(stats.at<int>(1, cv::CC_STAT_TOP), 0);
  EXPECT_EQ(stats.at<int>(1, cv::CC_STAT_WIDTH), 30);
  EXPECT_EQ(stats.at<int>(1, cv::CC_STAT_HEIGHT), 20);
  EXPECT_EQ(stats.at<int>(1, cv::CC_STAT_AREA), 600);
}

// Labels outside 0 to count - 1 (ag-merge's raster marks cells of no area
// with -1) count for no box.
TEST(RegionBoxes, LabelBoxesSkipsLabelsOutsideTheCount) {
  cv::Mat labels(4, 6, CV_32S, cv::Scalar(-1));
  labels(cv::Rect(1, 1, 3, 2)).setTo(1);
  labels.at<int>(3, 5) = 7;
  const cv::Mat stats = LabelBoxes(labels, 3);
  ASSERT_EQ(stats.rows, 3);
  EXPECT_EQ(stats.at<int>(0, cv::CC_STAT_AREA), 0);
  EXPECT_EQ(stats.at<int>(1, cv::CC_STAT_LEFT), 1);
  EXPECT_EQ(stats.at<int>(1, cv::CC_STAT_TOP), 1);
  EXPECT_EQ(stats.at<int>(1, cv::CC_STAT_WIDTH), 3);
  EXPECT_EQ(stats.at<int>(1, cv::CC_STAT_HEIGHT), 2);
  EXPECT_EQ(stats.at<int>(1, cv::CC_STAT_AREA), 6);
  EXPECT_EQ(stats.at<int>(2, cv::CC_STAT_AREA), 0);
}

// RunPieces against the cell-by-cell walk it replaced in ag-merge: a
// row-major scan that walks (breadth first, 4-connected) every piece of
// equal positive cells it meets, numbering the pieces as it finds them.
cv::Mat PiecesByWalking(const cv::Mat& cells) {
  cv::Mat values;
  cells.convertTo(values, CV_32S);
  cv::Mat piece(cells.size(), CV_32S, cv::Scalar(-1));
  int count = 0;
  for (int r = 0; r < cells.rows; ++r) {
    for (int c = 0; c < cells.cols; ++c) {
      const int value = values.at<int>(r, c);
      if (value <= 0 || piece.at<int>(r, c) >= 0) continue;
      std::deque<cv::Point> queue{{c, r}};
      piece.at<int>(r, c) = count;
      while (!queue.empty()) {
        const cv::Point p = queue.front();
        queue.pop_front();
        for (const cv::Point d :
             {cv::Point(1, 0), cv::Point(-1, 0), cv::Point(0, 1), cv::Point(0, -1)}) {
          const cv::Point q = p + d;
          if (q.x < 0 || q.y < 0 || q.x >= cells.cols || q.y >= cells.rows) continue;
          if (values.at<int>(q) != value || piece.at<int>(q) >= 0) continue;
          piece.at<int>(q) = count;
          queue.push_back(q);
        }
      }
      ++count;
    }
  }
  return piece;
}

void ExpectSamePieces(const cv::Mat& cells) {
  std::vector<PieceRun> runs;
  std::vector<int> piece_of_run;
  const int count = RunPieces(cells, &runs, &piece_of_run);
  ASSERT_EQ(runs.size(), piece_of_run.size());
  cv::Mat piece(cells.size(), CV_32S, cv::Scalar(-1));
  for (size_t i = 0; i < runs.size(); ++i) {
    const PieceRun& run = runs[i];
    ASSERT_LT(run.begin, run.end);
    ASSERT_LT(piece_of_run[i], count);
    if (i > 0) {
      ASSERT_TRUE(runs[i - 1].row < run.row ||
                  (runs[i - 1].row == run.row && runs[i - 1].end <= run.begin));
    }
    for (int c = run.begin; c < run.end; ++c) {
      ASSERT_EQ(cells.type() == CV_8U ? cells.at<uint8_t>(run.row, c) : cells.at<int>(run.row, c),
                run.value);
      piece.at<int>(run.row, c) = piece_of_run[i];
    }
  }
  const cv::Mat want = PiecesByWalking(cells);
  double most = -1;
  cv::minMaxLoc(want, nullptr, &most);
  EXPECT_EQ(count, static_cast<int>(most) + 1);
  EXPECT_EQ(cv::countNonZero(piece != want), 0);
}

TEST(RegionBoxes, RunPiecesEqualAWalkOnRandomMasksAndLabels) {
  std::mt19937 random(140);
  for (const double density : {0.05, 0.5, 0.95}) {
    for (const cv::Size size :
         {cv::Size(1, 1), cv::Size(1, 37), cv::Size(53, 1), cv::Size(64, 48), cv::Size(301, 177)}) {
      const cv::Mat mask = RandomMask(random, size.height, size.width, density);
      ExpectSamePieces(mask);
      // Labels -1 to 3 (ag-merge's raster holds -1 for unreached cells):
      // equal neighbours join, different ones do not.
      cv::Mat labels(size, CV_32S);
      std::uniform_int_distribution<int> label(-1, 3);
      for (int i = 0; i < size.area(); ++i) {
        labels.ptr<int>()[i] = mask.data[i] != 0 ? label(random) : 0;
      }
      ExpectSamePieces(labels);
    }
  }
}

TEST(RegionBoxes, RunPiecesJoinAUShapeAndKeepDiagonalsApart) {
  // A U whose arms meet only at the bottom: one piece, numbered first
  // although its right arm starts after another piece; two cells touching
  // only at a corner are two pieces.
  cv::Mat labels(6, 8, CV_32S, cv::Scalar(0));
  labels(cv::Rect(0, 0, 2, 5)).setTo(2);
  labels(cv::Rect(5, 2, 2, 3)).setTo(2);
  labels(cv::Rect(0, 5, 7, 1)).setTo(2);
  labels.at<int>(0, 3) = 2;
  labels.at<int>(1, 4) = 2;
  std::vector<PieceRun> runs;
  std::vector<int> piece_of_run;
  ASSERT_EQ(RunPieces(labels, &runs, &piece_of_run), 3);
  EXPECT_EQ(piece_of_run[0], 0);  // row 0, the left arm
  EXPECT_EQ(piece_of_run[1], 1);  // row 0, column 3
  EXPECT_EQ(piece_of_run[2], 0);  // row 1, the left arm
  EXPECT_EQ(piece_of_run[3], 2);  // row 1, column 4
  EXPECT_EQ(piece_of_run[4], 0);  // row 2, the left arm
  EXPECT_EQ(piece_of_run[5], 0);  // row 2, the right arm
  ExpectSamePieces(labels);
}

}  // namespace
}  // namespace areagraph
