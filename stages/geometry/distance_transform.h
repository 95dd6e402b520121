#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "stages/geometry/region_boxes.h"

namespace areagraph {

// Exact Euclidean distance transforms of a CV_8U mask: the distance (px) of
// every non-zero cell to the nearest zero cell. The values are those of
// cv::distanceTransform(mask, out, DIST_L2, DIST_MASK_PRECISE), which is also
// exact (tests/stages/geometry/distance_transform_test.cc compares them), but
// computed here on squared integer distances (Felzenszwalb and Huttenlocher's
// separable transform), rows split over OpenCV's pool (the results do not
// depend on the split), and only where the caller needs them: a cell next to
// zero cells costs a few operations, and the deepest distance or a threshold
// test skip most of the work.

// Every cell's distance, as CV_32F the mask's size (0 on zero cells).
cv::Mat ExactDistanceTransform(const cv::Mat& mask);

// The largest distance of any cell (0 for an empty mask): the maximum of
// ExactDistanceTransform(mask).
double DeepestDistance(const cv::Mat& mask);

// The largest distance within each label 0 .. count - 1 of `labels` (CV_32S,
// the mask's size; 0 for a label without cells): the maxima of
// ExactDistanceTransform(mask) over each label's cells. `depth`, if given, is
// that transform already.
std::vector<float> DeepestPerLabel(const cv::Mat& mask, const cv::Mat& labels, int count,
                                   const cv::Mat& depth = cv::Mat());

// DeepestPerLabel(mask, labels, count) with the labels (1 .. count - 1) given
// as runs of cells instead of a raster: the same maxima. Only the rows that
// hold a run are transformed (the column distances pass through the others),
// which on a mask where the single precision of OpenCV rounds (a row's value
// depends on the whole row) saves most of the work when the runs are few.
std::vector<float> DeepestPerRun(const cv::Mat& mask, const std::vector<PieceRun>& runs, int count);

// 1 where ExactDistanceTransform(mask) >= reach, else 0 (CV_8U).
cv::Mat DistanceAtLeast(const cv::Mat& mask, float reach);

// Whether ExactDistanceTransform computes every mask of this size itself
// (OpenCV computes it where its single precision is not exact, and a mask
// without zero cells): then a distance measured on a part of a mask, with
// the same nearest zero cells, equals the whole mask's.
bool ComputedExactly(cv::Size size);

}  // namespace areagraph
