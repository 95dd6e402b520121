#pragma once

#include <cstdint>
#include <opencv2/core.hpp>

#include "proto/artifacts.pb.h"

namespace areagraph {

// A CV_16U image the size of the map (frame width x height): 0 where no area
// is, id + 1 inside the area with that id (ExportIds: its stable id in a
// graph from ag-match, else its index). A pixel belongs to an area when its centre
// (c + .5, r + .5) lies inside the outer ring of polygon_px and outside its
// holes. Throws InputError for ids that do not fit (negative or > 65534) or a
// frame without a size.
cv::Mat AreaLabelImage(const proto::AreaGraph& graph);

// Sets to `value` every pixel of `image` (CV_16U) whose centre lies inside
// `polygon` (even-odd rule over the outer ring and the holes). Centres on a
// left or top edge count as inside, on a right or bottom edge as outside, so
// polygons that tile the plane give every pixel to exactly one of them.
void FillPolygonByPixelCentres(const proto::Polygon& polygon, uint16_t value, cv::Mat* image);

}  // namespace areagraph
