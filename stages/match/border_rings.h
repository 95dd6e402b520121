#pragma once

#include <set>
#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/match/passage_cutting.h"

namespace areagraph {

// A polygon's ring as BorderPoints, without a repeated closing point.
using BorderRing = std::vector<BorderPoint>;

BorderPoint ToBorderPoint(const proto::Point2& p);
void SetBorderPoint(const BorderPoint& p, proto::Point2* out);

// The rings of a polygon, outer first.
std::vector<BorderRing> Rings(const proto::Polygon& polygon);
// The polygon of rings, the first one outer.
proto::Polygon ToPolygon(const std::vector<BorderRing>& rings);

double SquaredDistance(const BorderPoint& a, const BorderPoint& b);
// Distance from p to the nearest edge of the rings.
double DistanceToRings(const BorderPoint& p, const std::vector<BorderRing>& rings);

// Area and centroid of polygon rings (holes run against the outer ring); the
// centroid stays unset for a polygon without area.
void AreaAndCentroid(const std::vector<BorderRing>& rings, double* area_m2,
                     proto::Point2* centroid);

std::set<BorderPoint> Vertices(const std::vector<BorderRing>& rings);

// Whether two polygons share a border edge (vertex for vertex, as
// neighbouring areas of one graph do).
bool ShareBorder(const proto::Polygon& a, const proto::Polygon& b);

}  // namespace areagraph
