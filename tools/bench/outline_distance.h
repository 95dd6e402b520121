#pragma once

#include "proto/geometry.pb.h"

namespace areagraph {

// The Hausdorff distance (pixels) between the boundaries of two polygons
// (outer rings and holes) given in pixels: the farthest any point of one
// boundary lies from the other. Points along segments are sampled every
// quarter pixel. Holes of `reference` smaller than `ignore_holes_below_px2`
// square pixels are left out (they are dropped on purpose).
double BoundaryDistancePx(const proto::Polygon& polygon, const proto::Polygon& reference,
                          double ignore_holes_below_px2);

}  // namespace areagraph
