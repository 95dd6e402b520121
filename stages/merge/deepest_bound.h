#pragma once

#include <opencv2/core.hpp>

namespace areagraph {

// A lower bound of DeepestDistance(mask) (CV_8U) that is cheap on masks that
// DeepestDistance takes to OpenCV's single precision (not ComputedExactly):
// the deepest exact distance over overlapping windows of at most
// kDeepestWindowCells a side, each bordered by zero cells. A border only
// brings zero cells nearer, and OpenCV's single-precision value of a cell is
// never below its exact distance (up to 4096 cells, beyond any window's), so
// the bound holds; a cell whose nearest zero cell lies in its window gets its
// exact distance. On masks that DeepestDistance computes exactly, it is
// DeepestDistance(mask) itself.
double DeepestDistanceLowerBound(const cv::Mat& mask);

inline constexpr int kDeepestWindowCells = 2048;

}  // namespace areagraph
