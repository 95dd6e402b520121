// RunEnd (geometry's, under RunPieces and merge's run loops) against a cell
// by cell scan, and CountAreaCells against LabelBoxes, on random rasters of
// long runs (the SIMD steps) and noise (the last cells).
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <random>

#include "stages/geometry/region_boxes.h"
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

// The end a cell by cell scan finds.
template <typename Cell>
int ScannedEnd(const Cell* row, int begin, int cols) {
  int c = begin + 1;
  while (c < cols && row[c] == row[begin]) ++c;
  return c;
}

TEST(RowRuns, RunEndAsTheCellByCellScan) {
  std::mt19937 random(33);
  int long_runs = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int type = trial % 2 ? CV_8U : CV_32S;
    const cv::Mat cells = RunsRaster(type, random, type == CV_8U ? 0 : -2, 3);
    for (int r = 0; r < cells.rows; ++r) {
      for (int begin = 0; begin < cells.cols; ++begin) {
        const int want = type == CV_8U ? ScannedEnd(cells.ptr<uint8_t>(r), begin, cells.cols)
                                       : ScannedEnd(cells.ptr<int>(r), begin, cells.cols);
        const int got = type == CV_8U ? RunEnd(cells.ptr<uint8_t>(r), begin, cells.cols)
                                      : RunEnd(cells.ptr<int>(r), begin, cells.cols);
        ASSERT_EQ(got, want) << "trial " << trial << ", row " << r << ", from " << begin;
        if (want - begin > 16) ++long_runs;
      }
    }
  }
  EXPECT_GT(long_runs, 1000);  // the 16-byte and 4-label steps ran
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
