#pragma once

#include <string>

#include "proto/artifacts.pb.h"

namespace areagraph {

// The Area Graph as a GeoJSON FeatureCollection in world metres (x, y of the
// map frame; not WGS 84 as RFC 7946 would have it, since a map has no
// geographic anchor). One feature per line:
// - each area a Polygon: closed outer ring counter-clockwise, closed holes
//   clockwise (RFC 7946 winding); properties id, kind (room, corridor,
//   dead_end), area_m2, name (area_<id>);
// - each passage a LineString along border_m, the border its two areas
//   share (whose points are vertices of both polygons), or along segment_m
//   when it has none; properties id, kind ("passage"), width_m, from and to
//   (area ids).
// Areas come first. Throws InputError for coordinates that are not finite.
std::string AreaGraphToGeoJson(const proto::AreaGraph& graph);

}  // namespace areagraph
