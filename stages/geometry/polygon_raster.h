#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "proto/geometry.pb.h"

namespace areagraph {

// Paints `polygon` (pixel coordinates: cell (c, r) spans [c, c+1] x [r, r+1])
// into `image` with `value`, holes left out: every cell whose centre lies
// inside, plus the cells that the outline runs through.
void FillPolygon(const proto::Polygon& polygon, int value, cv::Mat* image);

// A CV_32S image of `size`: 0, then FillPolygon(*polygons[i].first,
// polygons[i].second) for i in order. The polygons are painted each into a
// box of its own, in parallel ranges, and the boxes copied in order in
// parallel ranges of rows: the same cells as FillPolygon, whose painting does
// not depend on where the polygon lies, only on the image's edges, which a
// box shares where it reaches them.
cv::Mat PolygonLabels(const std::vector<std::pair<const proto::Polygon*, int>>& polygons,
                      cv::Size size);

// A CV_8U mask of `size` with the cells of `polygon` set to 255.
cv::Mat PolygonMask(const proto::Polygon& polygon, cv::Size size);

// The mask of the map's boundaries: every polygon of `parts` (a Topology or
// Cut Graph's part_boundaries), or `boundary` alone when there are none (an
// artifact from before parts were kept).
cv::Mat BoundaryMask(const google::protobuf::RepeatedPtrField<proto::Polygon>& parts,
                     const proto::Polygon& boundary, cv::Size size);

}  // namespace areagraph
