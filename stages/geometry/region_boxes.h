#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace areagraph {

// cv::connectedComponentsWithStats(mask, *labels, *stats, centroids,
// connectivity, CV_32S) without the centroids: the same labels (CV_32S) and
// the same CC_STAT_LEFT, TOP, WIDTH, HEIGHT and AREA columns (stats is
// count x 5, CV_32S; a label without cells, which only the background can
// be, gets zeros). Returns the number of labels, background included.
//
// Why not OpenCV's: its statistics op runs per cell, background included,
// and sums the centroids in 64 bits; that was 2.5 times the labelling
// itself (issue 14, docs/performance.md, 2026-12-02). Here the labels come
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

}  // namespace areagraph
