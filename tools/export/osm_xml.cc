#include "tools/export/osm_xml.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/error.h"
#include "tools/export/markup_escape.h"

namespace areagraph {

namespace {

std::string NodeXml(int64_t id, const LatLon& position, const std::string& tags) {
  const std::string head = "  <node id=\"" + std::to_string(id) + "\" visible=\"true\" lat=\"" +
                           FixedDecimals(position.lat_deg, 10) + "\" lon=\"" +
                           FixedDecimals(position.lon_deg, 10) + "\"";
  return tags.empty() ? head + "/>\n" : head + ">\n" + tags + "  </node>\n";
}

}  // namespace

std::string FixedDecimals(double value, int decimals) {
  const int length = std::snprintf(nullptr, 0, "%.*f", decimals, value);
  std::string text(static_cast<size_t>(std::max(length, 0)) + 1, '\0');
  std::snprintf(text.data(), text.size(), "%.*f", decimals, value);
  text.pop_back();
  return text;
}

std::string OsmTag(const std::string& key, const std::string& value) {
  return "    <tag k=\"" + MarkupEscaped(key) + "\" v=\"" + MarkupEscaped(value) + "\"/>\n";
}

std::string OsmWayXml(int64_t id, const std::vector<int64_t>& nodes, const std::string& tags) {
  std::string xml = "  <way id=\"" + std::to_string(id) + "\" visible=\"true\">\n";
  for (const int64_t node : nodes) xml += "    <nd ref=\"" + std::to_string(node) + "\"/>\n";
  return xml + tags + "  </way>\n";
}

int64_t OsmNodeTable::NodeAt(double x_m, double y_m) {
  if (!std::isfinite(x_m) || !std::isfinite(y_m)) {
    throw InputError("the Area Graph has a vertex that is not a finite number");
  }
  const std::pair<int64_t, int64_t> key{std::llround(x_m * 1e6), std::llround(y_m * 1e6)};
  auto [it, inserted] = ids_.emplace(key, 0);
  if (inserted) {
    const LatLon position = MetresToLatLon(anchor_, x_m, y_m);
    if (!(std::fabs(position.lat_deg) <= 90) || !(std::fabs(position.lon_deg) <= 180)) {
      ids_.erase(it);
      throw InputError("the Area Graph's point (" + FixedDecimals(x_m, 3) + ", " +
                       FixedDecimals(y_m, 3) + ") m lies off the globe from the anchor (latitude " +
                       FixedDecimals(position.lat_deg, 3) +
                       "); osmAG needs map coordinates in local metres near "
                       "--anchor-lat/--anchor-lon");
    }
    it->second = NextId();
    xml_ += NodeXml(it->second, position, "");
  }
  return it->second;
}

void OsmNodeTable::AddAnchorNode(const std::string& tags) {
  xml_ += NodeXml(NextId(), {anchor_.lat_deg, anchor_.lon_deg}, tags);
}

}  // namespace areagraph
