// PiecesOverRuns against RunPieces, and CountAreaCells against LabelBoxes,
// on random rasters of long runs (the SIMD steps) and noise (the last cells).
#include "stages/merge/row_runs.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <random>

#include "stages/merge/area_raster.h"

namespace areagraph::testing {
namespace {

// Rows of runs of random lengths (1 to 40) and values in [lo, hi].
cv::Mat RunsRaster(int type, std::mt19937& random, int lo, int hi) {
  auto uniform = [&](int a, int b) { return std::uniform_int_distribution<int>(a, b)(random); };
  const int rows = uniform(1, 40), cols = uniform(1, 90);
  cv::Mat cells(rows, cols, type);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols;) {
      const int value = uniform(lo, hi), end = std::min(cols, c + uniform(1, 40));
      for (; c < end; ++c) {
        if (type == CV_8U) {
          cells.at<uint8_t>(r, c) = static_cast<uint8_t>(value);
        } else {
          cells.at<int>(r, c) = value;
        }
      }
    }
  }
  return cells;
}

TEST(RowRuns, PiecesAsRunPieces) {
  std::mt19937 random(33);
  int pieces = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int type = trial % 2 ? CV_8U : CV_32S;
    const cv::Mat cells = RunsRaster(type, random, type == CV_8U ? 0 : -2, 3);
    std::vector<PieceRun> want_runs, got_runs;
    std::vector<int> want_pieces, got_pieces;
    const int want = RunPieces(cells, &want_runs, &want_pieces);
    ASSERT_EQ(PiecesOverRuns(cells, &got_runs, &got_pieces), want);
    ASSERT_EQ(got_runs.size(), want_runs.size());
    for (size_t i = 0; i < want_runs.size(); ++i) {
      EXPECT_EQ(got_runs[i].row, want_runs[i].row);
      EXPECT_EQ(got_runs[i].begin, want_runs[i].begin);
      EXPECT_EQ(got_runs[i].end, want_runs[i].end);
      EXPECT_EQ(got_runs[i].value, want_runs[i].value);
    }
    EXPECT_EQ(got_pieces, want_pieces);
    pieces += want;
  }
  EXPECT_GT(pieces, 1000);
}

TEST(RowRuns, AreaCellsAsLabelBoxes) {
  std::mt19937 random(34);
  for (int trial = 0; trial < 200; ++trial) {
    AreaRaster raster;
    raster.labels = RunsRaster(CV_32S, random, -1, 9);
    const int count = 7;  // labels 8 and 9 are no area of these
    raster.cell_count.assign(count, -1);
    CountAreaCells(&raster);
    const cv::Mat stats = LabelBoxes(raster.labels, count + 1);
    for (int k = 0; k < count; ++k) {
      const int* s = stats.ptr<int>(k + 1);
      ASSERT_EQ(raster.cell_count[k], s[cv::CC_STAT_AREA]);
      const cv::Rect want = s[cv::CC_STAT_AREA] == 0
                                ? cv::Rect()
                                : cv::Rect(s[cv::CC_STAT_LEFT], s[cv::CC_STAT_TOP],
                                           s[cv::CC_STAT_WIDTH], s[cv::CC_STAT_HEIGHT]);
      ASSERT_EQ(raster.boxes[k], want);
    }
  }
}

}  // namespace
}  // namespace areagraph::testing
