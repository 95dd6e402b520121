// GrowIntoCleared against GrowLabels: after a saturating growth, random runs
// of labelled cells are cleared and both grow them back; the labels must be
// the same cell for cell.
#include "stages/merge/label_growth.h"

#include <gtest/gtest.h>

#include <random>

namespace areagraph::testing {
namespace {

TEST(LabelGrowth, IntoClearedRunsAsFromEveryCell) {
  std::mt19937 random(21);
  auto uniform = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(random); };
  int regrown = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int rows = uniform(1, 60), cols = uniform(1, 80);
    cv::Mat domain(rows, cols, CV_8U);
    cv::randu(domain, 0, 5);  // one cell in five outside the domain
    cv::Mat labels = cv::Mat::zeros(rows, cols, CV_32S);
    for (int k = 0; k < uniform(1, 12); ++k) {
      const int r = uniform(0, rows - 1), c = uniform(0, cols - 1);
      if (domain.at<uint8_t>(r, c)) labels.at<int>(r, c) = uniform(-1, 6) | 1;
    }
    GrowLabels(domain, &labels);
    std::vector<PieceRun> cleared;
    for (int k = 0; k < uniform(0, 15); ++k) {
      const int r = uniform(0, rows - 1), begin = uniform(0, cols - 1);
      int end = begin;
      int* row = labels.ptr<int>(r);
      while (end < cols && end - begin < 9 && row[end] != 0) ++end;
      if (end == begin) continue;
      std::fill(row + begin, row + end, 0);
      cleared.push_back({r, begin, end, 0});
    }
    cv::Mat want = labels.clone();
    GrowLabels(domain, &want);
    cv::Mat got = labels.clone();
    GrowIntoCleared(cleared, domain, &got);
    ASSERT_EQ(cv::countNonZero(got != want), 0) << "trial " << trial;
    regrown += cv::countNonZero(want != labels);
  }
  EXPECT_GT(regrown, 1000);
}

}  // namespace
}  // namespace areagraph::testing
