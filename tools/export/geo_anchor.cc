#include "tools/export/geo_anchor.h"

#include <cmath>

namespace areagraph {

namespace {

constexpr double kEarthRadiusM = 6378137.0;
constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;

}  // namespace

LatLon MetresToLatLon(const GeoAnchor& anchor, double x_m, double y_m) {
  const double lat0_rad = anchor.lat_deg / kDegreesPerRadian;
  return {anchor.lat_deg + y_m / kEarthRadiusM * kDegreesPerRadian,
          anchor.lon_deg + x_m / (kEarthRadiusM * std::cos(lat0_rad)) * kDegreesPerRadian};
}

}  // namespace areagraph
