#pragma once

#include <string>
#include <vector>

#include "proto/artifacts.pb.h"

namespace areagraph {

// The area's polygon in world metres: polygon_m, or polygon_px converted with
// the graph's frame when polygon_m is empty.
proto::Polygon AreaPolygonMetres(const proto::AreaGraph& graph, const proto::Area& area);

// The area's polygon in pixels: polygon_px, or polygon_m converted back.
proto::Polygon AreaPolygonPixels(const proto::AreaGraph& graph, const proto::Area& area);

// The ring's points, reversed if needed so that the ring runs
// counter-clockwise (in a y-up frame) when `counter_clockwise`, else clockwise.
std::vector<proto::Point2> OrientedRing(const proto::Ring& ring, bool counter_clockwise);

// Throws InputError naming `what` when a vertex is NaN or infinite.
void RequireFiniteVertices(const proto::Polygon& polygon, const std::string& what);

// "room", "corridor" or "dead_end", the names used in every export.
std::string AreaKindName(proto::AreaKind kind);

// The passage as a line in world metres: border_m, the border its areas share
// (whose points are vertices of both polygons), or segment_m's two ends when
// it has none. Throws InputError naming the passage for a coordinate that is
// not finite.
std::vector<proto::Point2> PassageLine(const proto::Passage& passage);

// "area_<id>", how exports name an area.
std::string AreaName(int id);

}  // namespace areagraph
