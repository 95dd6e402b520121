#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace areagraph {

// An 8-connected region of a mask's non-zero cells: its cells in row-major
// order and their bounding box.
struct CellRegion {
  std::vector<cv::Point> cells;
  cv::Rect box;
};

// For each region of `mask` (CV_8U), the deepest distance of its cells to a
// zero cell of `mask` as ExactDistanceTransform(mask) gives it, except that
// a region whose twice exact deepest distance already reaches
// `min_thickness_px` may get that instead: where the transform takes
// OpenCV's single precision (not ComputedExactly), its values are never
// below the exact ones, so such a region reaches the thickness either way,
// and only the others need the rows of the whole mask. The exact distances
// come from each region's box with a margin of one zero cell.
std::vector<float> DeepestOfRegions(const cv::Mat& mask, const std::vector<CellRegion>& regions,
                                    double min_thickness_px);

}  // namespace areagraph
