#include "tools/export/geo_anchor.h"

#include <cmath>

#include "common/error.h"
#include "common/text.h"

namespace areagraph {

namespace {

constexpr double kEarthRadiusM = 6378137.0;
constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;

}  // namespace

void CheckGeoAnchor(const GeoAnchor& anchor) {
  if (!(anchor.lat_deg >= -89 && anchor.lat_deg <= 89)) {  // NaN fails
    throw OptionsError("--anchor-lat must be a latitude in [-89, 89] degrees, got " +
                       FormatNumber(anchor.lat_deg));
  }
  if (!(anchor.lon_deg >= -180 && anchor.lon_deg <= 180)) {
    throw OptionsError("--anchor-lon must be a longitude in [-180, 180] degrees, got " +
                       FormatNumber(anchor.lon_deg));
  }
}

LatLon MetresToLatLon(const GeoAnchor& anchor, double x_m, double y_m) {
  const double lat0_rad = anchor.lat_deg / kDegreesPerRadian;
  return {anchor.lat_deg + y_m / kEarthRadiusM * kDegreesPerRadian,
          anchor.lon_deg + x_m / (kEarthRadiusM * std::cos(lat0_rad)) * kDegreesPerRadian};
}

}  // namespace areagraph
