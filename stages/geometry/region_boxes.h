#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "stages/geometry/disjoint_sets.h"

namespace areagraph {

// cv::connectedComponentsWithStats(mask, *labels, *stats, centroids,
// connectivity, CV_32S) without the centroids: the same labels (CV_32S) and
// the same CC_STAT_LEFT, TOP, WIDTH, HEIGHT and AREA columns (stats is
// count x 5, CV_32S; a label without cells, which only the background can
// be, gets zeros). Returns the number of labels, background included.
//
// Why not OpenCV's: its statistics op runs per cell, background included,
// and sums the centroids in 64 bits; that was 2.5 times the labelling
// itself. Here the labels come
// from cv::connectedComponents (the same algorithm, so the same numbering)
// and one pass over the rows' runs of equal labels gives the boxes.
// tests/stages/geometry/region_boxes_test.cc holds it to OpenCV's.
int LabelRegionsWithBoxes(const cv::Mat& mask, int connectivity, cv::Mat* labels, cv::Mat* stats);

// The boxes and cell counts of the labels 0 to count - 1 of `labels` (CV_32S;
// other values are skipped), in the layout of LabelRegionsWithBoxes' stats:
// one pass over the rows' runs of equal labels.
cv::Mat LabelBoxes(const cv::Mat& labels, int count);

// The cells of `labels` (CV_32S) equal to `label` inside `box` as a CV_8U
// mask (255), with a margin of one zero cell all round, so that a distance
// transform of the mask sees the region's outline.
cv::Mat LabelMaskInBox(const cv::Mat& labels, int label, const cv::Rect& box);

// The end of the run of cells equal to row[begin] (begin < cols): the first
// column after `begin` that differs, or cols. Compares 4 labels or 16 bytes
// at a time where SSE2 is: label rasters are mostly long runs.
int RunEnd(const int* row, int begin, int cols);
int RunEnd(const uint8_t* row, int begin, int cols);

// A run of equal cells in one row: columns [begin, end) of `row`.
struct PieceRun {
  int row;
  int begin;
  int end;
  int value;
};

// The 4-connected pieces of equal positive cells of `cells` (CV_8U or
// CV_32S), found over the rows' runs instead of cell by cell: `runs` in
// row-major order, and per run its piece, the pieces numbered in the
// row-major order of their first cells (the order a row-major scan that
// walks each piece it meets would find them). Returns the number of pieces.
int RunPieces(const cv::Mat& cells, std::vector<PieceRun>* runs, std::vector<int>* piece_of_run);

// Joins runs (fields row, begin, end; row-major, each row's in column
// order; row r's are runs[row_start[r], row_start[r + 1])) of neighbouring
// rows that overlap, or also touch at a corner when `eight_connected`, and
// for which same(above, below) holds. Returns per run its piece, numbered
// in the order of the pieces' first runs; `count` gets the number.
// One sweep per pair of rows: RunPieces' and clean's FindRunRegions' join.
template <typename Run, typename Same>
std::vector<int> JoinRowRuns(const std::vector<Run>& runs, const std::vector<size_t>& row_start,
                             bool eight_connected, Same same, int* count) {
  const int corner = eight_connected ? 1 : 0;
  DisjointSets pieces(runs.size());
  for (size_t r = 1; r + 1 < row_start.size(); ++r) {
    size_t above = row_start[r - 1];
    for (size_t i = row_start[r]; i < row_start[r + 1]; ++i) {
      while (above < row_start[r] && runs[above].end + corner <= runs[i].begin) ++above;
      for (size_t a = above; a < row_start[r] && runs[a].begin < runs[i].end + corner; ++a) {
        if (same(runs[a], runs[i])) pieces.Union(static_cast<int>(a), static_cast<int>(i));
      }
    }
  }
  return pieces.DenseLabels(count);
}

}  // namespace areagraph
