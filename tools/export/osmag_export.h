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
// Area Graph authors, with ids from ExportIds (the stable ids of a graph
// from ag-match, else the indices; the root says which):
// - a root node at the anchor: name=root, osmAG:type=root, osmAG:map,
//   areagraph:ids=stable|index;
// - one node per distinct position at OSM's precision (7 decimals of a
//   degree); outlines through the same vertex share it. Positions are snap
//   rounded (snap_rounding.h), so no outline comes to cross itself;
// - a structure area (closed way around every area, 0.1 m outside their
//   bounding box): osmAG:type=area, osmAG:areaType=structure, indoor=level,
//   name=<map_name>, level;
// - each area a closed counter-clockwise way: osmAG:type=area,
//   osmAG:areaType=room (the spec's value for every inner area that is not
//   stairs or an elevator), areagraph:kind=room|corridor|dead_end (our finer
//   kind), areagraph:index, areagraph:stable_id (ag-match's graphs),
//   osmAG:parent=<map_name>, indoor=room, name=area_<id>, level, height.
//   An area with holes, or whose outline comes back within OSM's precision
//   of itself (cut there into loops that share the node), is OSM's
//   multipolygon instead: a relation type=multipolygon with those tags and
//   untagged closed ways as its outer and inner members;
// - each passage a way over the border its areas share (PassageLine), every
//   node of which is a node of a ring of both areas, outer or inner:
//   osmAG:type=passage, osmAG:from=area_<a>, osmAG:to=area_<b>,
//   name=passage_<id>, level, areagraph:width=<m>, areagraph:index,
//   areagraph:stable_id. No indoor=door, door or width: JOSM reads those on
//   a way as a door node in the wrong place. A point of the line that lies
//   on an area's ring but is not yet a vertex of it (segment_m of older
//   graphs) is inserted there; one that lies on no ring (a passage whose
//   areas share no border) stays a node of the passage only.
// Nodes come first, then the structure, the area ways and rings, the
// passages, and the multipolygon relations. Throws InputError for an area
// with fewer than three vertices or coordinates that are not finite.
std::string AreaGraphToOsmAg(const proto::AreaGraph& graph, const OsmAgSettings& settings);

}  // namespace areagraph
