#pragma once

#include <opencv2/core.hpp>

#include "stages/geometry/edge_polygon.h"

namespace areagraph {

// Paints the cells of `path` (pixel coordinates, each point in the cell that
// holds it) with `value` in `labels` (CV_32S) and with 1 in `marks` (CV_8U,
// the same size): the cells of cv::polylines(image, cells, false, value, 1,
// cv::LINE_4) on each, in one walk. Segments within one cell, between
// 4-neighbours or along a row or column inside the image are painted
// directly (no other 4-connected line joins their ends); the others go
// through cv::LineIterator as cv::polylines does.
void PaintPathCells(const PointList& path, int value, cv::Mat* labels, cv::Mat* marks);

}  // namespace areagraph
