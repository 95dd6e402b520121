#pragma once

#include <opencv2/core.hpp>

#include "stages/geometry/cell_grid.h"

namespace areagraph {

// The cores of PartitionFreeSpace: 1 on the cells of `domain` (CV_8U, the
// grid's size) whose distance to the nearest non-free cell of `grid` is at
// least min_gap_px / 2, else 0 (CV_8U). The distance is
// ExactDistanceTransform's of the free cells (DistanceAtLeast's threshold).
// Where that transform is exact (ComputedExactly) and the reach small, the
// column distances are counted only up to the reach, one byte a cell, and
// the rows skip eight cells at a time where no column is near an obstacle
// or every one is on one; otherwise DistanceAtLeast decides.
cv::Mat CoreCells(const CellGrid& grid, const cv::Mat& domain, double min_gap_px);

}  // namespace areagraph
