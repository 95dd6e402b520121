#include "tools/export/osm_xml.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/error.h"
#include "tools/export/markup_escape.h"

namespace areagraph {

namespace {

// OSM's precision: the OSM database, and JOSM when it looks for duplicated
// nodes, know positions to 7 decimals of a degree (about a centimetre).
constexpr int kOsmDegreeDecimals = 7;
constexpr double kDegreeUnits = 1e7;

GridPoint GridPointOf(const LatLon& position) {
  return {std::llround(position.lon_deg * kDegreeUnits),
          std::llround(position.lat_deg * kDegreeUnits)};
}

std::string NodeXml(int64_t id, const GridPoint& point, const std::string& tags) {
  const std::string head = "  <node id=\"" + std::to_string(id) + "\" visible=\"true\" lat=\"" +
                           FixedDecimals(point.second / kDegreeUnits, kOsmDegreeDecimals) +
                           "\" lon=\"" +
                           FixedDecimals(point.first / kDegreeUnits, kOsmDegreeDecimals) + "\"";
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

std::string OsmRelationXml(int64_t id, const std::vector<OsmWayMember>& members,
                           const std::string& tags) {
  std::string xml = "  <relation id=\"" + std::to_string(id) + "\" visible=\"true\">\n";
  for (const OsmWayMember& member : members) {
    xml += "    <member type=\"way\" ref=\"" + std::to_string(member.way) + "\" role=\"" +
           MarkupEscaped(member.role) + "\"/>\n";
  }
  return xml + tags + "  </relation>\n";
}

GridPosition OsmNodeTable::GridPositionOf(double x_m, double y_m) const {
  if (!std::isfinite(x_m) || !std::isfinite(y_m)) {
    throw InputError("the Area Graph has a vertex that is not a finite number");
  }
  const LatLon position = MetresToLatLon(anchor_, x_m, y_m);
  if (!(std::fabs(position.lat_deg) <= 90) || !(std::fabs(position.lon_deg) <= 180)) {
    throw InputError("the Area Graph's point (" + FixedDecimals(x_m, 3) + ", " +
                     FixedDecimals(y_m, 3) + ") m lies off the globe from the anchor (latitude " +
                     FixedDecimals(position.lat_deg, 3) +
                     "); osmAG needs map coordinates in local metres near "
                     "--anchor-lat/--anchor-lon");
  }
  return {position.lon_deg * kDegreeUnits, position.lat_deg * kDegreeUnits};
}

int64_t OsmNodeTable::NodeAt(const GridPoint& point) {
  auto [it, inserted] = ids_.emplace(point, 0);
  if (inserted) {
    it->second = NextId();
    xml_ += NodeXml(it->second, point, "");
  }
  return it->second;
}

int64_t OsmNodeTable::NodeAt(double x_m, double y_m) {
  const GridPosition position = GridPositionOf(x_m, y_m);
  return NodeAt(GridPoint{std::llround(position.x), std::llround(position.y)});
}

void OsmNodeTable::AddAnchorNode(const std::string& tags) {
  xml_ += NodeXml(NextId(), GridPointOf({anchor_.lat_deg, anchor_.lon_deg}), tags);
}

}  // namespace areagraph
