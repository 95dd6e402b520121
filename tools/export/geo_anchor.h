#pragma once

namespace areagraph {

// Where the map's world origin (0, 0) is placed on the globe. The default is
// ShanghaiTech University, where osmAG comes from.
struct GeoAnchor {
  double lat_deg = 31.17947;
  double lon_deg = 121.59042;
};

struct LatLon {
  double lat_deg = 0;
  double lon_deg = 0;
};

// World metres (x east, y north) to latitude and longitude on the local
// tangent plane at `anchor`: lat = lat0 + y / R, lon = lon0 + x / (R cos lat0),
// with R = 6378137 m (WGS 84 equatorial radius). Good to millimetres over a
// building.
LatLon MetresToLatLon(const GeoAnchor& anchor, double x_m, double y_m);

}  // namespace areagraph
