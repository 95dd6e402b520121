#pragma once

#include <string>

#include "proto/artifacts.pb.h"

namespace areagraph {

// Where the map's world origin (0, 0) is placed on the globe. The default is
// ShanghaiTech University, where osmAG comes from.
struct GeoAnchor {
  double lat_deg = 31.17947;
  double lon_deg = 121.59042;
};

// Throws OptionsError unless the anchor is a finite latitude in [-89, 89]
// (the tangent plane degenerates at the poles) and longitude in [-180, 180].
void CheckGeoAnchor(const GeoAnchor& anchor);

struct LatLon {
  double lat_deg = 0;
  double lon_deg = 0;
};

// World metres (x east, y north) to latitude and longitude on the local
// tangent plane at `anchor`: lat = lat0 + y / R, lon = lon0 + x / (R cos lat0),
// with R = 6378137 m (WGS 84 equatorial radius). Good to millimetres over a
// building.
LatLon MetresToLatLon(const GeoAnchor& anchor, double x_m, double y_m);

// The Area Graph as osmAG XML (OSM 0.6) that JOSM opens:
// - a root node at the anchor tagged name=root (the osmAG marker),
//   osmAG:type=root and osmAG:map=<map_name>;
// - one node per distinct polygon vertex (vertices shared by areas, and
//   passage ends on a vertex, share the node);
// - each area a closed way (first node repeated) of its outer ring,
//   counter-clockwise, tagged osmAG:type=area, osmAG:areaType=room|corridor|
//   dead_end, name=area_<id>, indoor=room. Holes are not written (osmAG areas
//   are simple closed ways);
// - each passage a two-node way along segment_m tagged osmAG:type=passage,
//   osmAG:from=area_<a>, osmAG:to=area_<b>, name=passage_<id>, width=<m>.
// Nodes come first, then area ways, then passage ways. New objects have
// negative ids, unique across nodes and ways. Throws InputError for an area
// with fewer than three vertices, or coordinates that are not finite or lie
// off the globe from the anchor.
std::string AreaGraphToOsmAg(const proto::AreaGraph& graph, const std::string& map_name,
                             const GeoAnchor& anchor);

}  // namespace areagraph
