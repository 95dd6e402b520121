#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "stages/geometry/edge_polygon.h"

namespace areagraph {

// The outline of a region of cells, in pixel coordinates (cell (c, r) spans
// [c, c+1] x [r, r+1]).
struct RegionOutline {
  PointList outer;
  std::vector<PointList> holes;
};

// Traces the cells of `labels` (CV_32S) equal to `label` inside `box` along
// the cell edges, so that neighbouring regions share their borders exactly
// and the polygon's area is the cell count. Cells that touch only at a
// corner are kept apart (4-connectivity): the ring cuts such a corner by a
// hair so that it stays simple. For a 4-connected region the result is one
// outer ring (clockwise on screen) and its holes.
RegionOutline TraceRegionOutline(const cv::Mat& labels, int label, const cv::Rect& box);

// The outline with every ring simplified by Douglas-Peucker (`tolerance_px`),
// or the outline itself when the simplified rings would not form a valid
// polygon.
RegionOutline SimplifyOutline(const RegionOutline& outline, double tolerance_px);

}  // namespace areagraph
