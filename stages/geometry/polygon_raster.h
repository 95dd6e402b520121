#pragma once

#include <opencv2/core.hpp>

#include "proto/geometry.pb.h"

namespace areagraph {

// Paints `polygon` (pixel coordinates: cell (c, r) spans [c, c+1] x [r, r+1])
// into `image` with `value`, holes left out: every cell whose centre lies
// inside, plus the cells that the outline runs through.
void FillPolygon(const proto::Polygon& polygon, int value, cv::Mat* image);

// A CV_8U mask of `size` with the cells of `polygon` set to 255.
cv::Mat PolygonMask(const proto::Polygon& polygon, cv::Size size);

}  // namespace areagraph
