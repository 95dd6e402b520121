#pragma once

#include <string>

#include "proto/artifacts.pb.h"
#include "tools/export/geo_anchor.h"

namespace areagraph {

struct OsmAgSettings {
  // Written as osmAG:map on the root node and as the structure area's name.
  std::string map_name;
  GeoAnchor anchor;
  // The floor, tagged `level` on every way (osmAG's multi-floor key).
  int level = 0;
  // The floor's height in metres, tagged `height` on every area when > 0; a
  // 2D map does not know it.
  double height_m = 0;
};

// The Area Graph as osmAG XML (OSM 0.6, <osm upload="never"> so that JOSM
// never sends it to openstreetmap.org), following the osmAG standard of the
// Area Graph authors:
// - a root node at the anchor: name=root, osmAG:type=root, osmAG:map;
// - one node per distinct vertex; outlines through the same vertex share it;
// - a structure area (closed way around every area, 0.1 m outside their
//   bounding box): osmAG:type=area, osmAG:areaType=structure, indoor=level,
//   name=<map_name>, level;
// - each area a closed counter-clockwise way of its outer ring (holes are not
//   written): osmAG:type=area, osmAG:areaType=room (the spec's value for every
//   inner area that is not stairs or an elevator), areagraph:kind=room|
//   corridor|dead_end (our finer kind), osmAG:parent=<map_name>,
//   indoor=room, name=area_<id>, level, height;
// - each passage a way over the border its areas share (PassageLine), every
//   node of which is a node of both area ways: osmAG:type=passage,
//   osmAG:from=area_<a>, osmAG:to=area_<b>, indoor=door, door=yes,
//   name=passage_<id>, level, width=<m>. A point of the line that is not yet
//   a vertex of an area's outline (segment_m of older graphs) is inserted
//   into that outline on its nearest edge.
// Nodes come first, then the structure, the areas and the passages. Throws
// InputError for an area with fewer than three vertices or coordinates that
// are not finite.
std::string AreaGraphToOsmAg(const proto::AreaGraph& graph, const OsmAgSettings& settings);

}  // namespace areagraph
