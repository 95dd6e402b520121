#include "tools/export/osm_xml.h"

#include <cmath>
#include <cstdio>

#include "common/error.h"
#include "tools/export/markup_escape.h"

namespace areagraph {

namespace {

std::string NodeXml(int64_t id, const LatLon& position, const std::string& tags) {
  char head[160];
  std::snprintf(head, sizeof(head),
                "  <node id=\"%lld\" visible=\"true\" lat=\"%.10f\" lon=\"%.10f\"",
                static_cast<long long>(id), position.lat_deg, position.lon_deg);
  return tags.empty() ? std::string(head) + "/>\n"
                      : std::string(head) + ">\n" + tags + "  </node>\n";
}

}  // namespace

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
    it->second = NextId();
    xml_ += NodeXml(it->second, MetresToLatLon(anchor_, x_m, y_m), "");
  }
  return it->second;
}

void OsmNodeTable::AddAnchorNode(const std::string& tags) {
  xml_ += NodeXml(NextId(), {anchor_.lat_deg, anchor_.lon_deg}, tags);
}

}  // namespace areagraph
