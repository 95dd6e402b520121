#include "tools/export/osmag_export.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <utility>
#include <vector>

#include "common/error.h"
#include "tools/export/area_polygons.h"
#include "tools/export/markup_escape.h"

namespace areagraph {

namespace {

constexpr double kEarthRadiusM = 6378137.0;
constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;

std::string Tag(const std::string& key, const std::string& value) {
  return "    <tag k=\"" + MarkupEscaped(key) + "\" v=\"" + MarkupEscaped(value) + "\"/>\n";
}

// `value` with `decimals` digits after the point, however long it gets.
std::string Fixed(double value, int decimals) {
  const int length = std::snprintf(nullptr, 0, "%.*f", decimals, value);
  std::string text(static_cast<size_t>(std::max(length, 0)) + 1, '\0');
  std::snprintf(text.data(), text.size(), "%.*f", decimals, value);
  text.pop_back();
  return text;
}

std::string Metres(double value) { return Fixed(value, 3); }

// Hands out negative ids and one node per distinct position (to the micrometre).
class OsmNodeTable {
 public:
  explicit OsmNodeTable(const GeoAnchor& anchor) : anchor_(anchor) {}

  int64_t NextId() { return next_id_--; }

  int64_t NodeAt(double x_m, double y_m) {
    if (!std::isfinite(x_m) || !std::isfinite(y_m)) {
      throw InputError("the Area Graph has a vertex that is not a finite number");
    }
    const LatLon position = MetresToLatLon(anchor_, x_m, y_m);
    if (!(std::fabs(position.lat_deg) <= 90) || !(std::fabs(position.lon_deg) <= 180)) {
      throw InputError("the Area Graph's point (" + Metres(x_m) + ", " + Metres(y_m) +
                       ") m lies off the globe from the anchor (latitude " +
                       Fixed(position.lat_deg, 3) +
                       "); osmAG needs map coordinates in local "
                       "metres near --anchor-lat/--anchor-lon");
    }
    const std::pair<int64_t, int64_t> key{std::llround(x_m * 1e6), std::llround(y_m * 1e6)};
    auto [it, inserted] = ids_.emplace(key, 0);
    if (inserted) {
      it->second = NextId();
      xml_ += NodeXml(it->second, position, "");
    }
    return it->second;
  }

  void AddRoot(const std::string& map_name) {
    xml_ += NodeXml(NextId(), {anchor_.lat_deg, anchor_.lon_deg},
                    Tag("name", "root") + Tag("osmAG:type", "root") + Tag("osmAG:map", map_name));
  }

  const std::string& xml() const { return xml_; }

 private:
  static std::string NodeXml(int64_t id, const LatLon& position, const std::string& tags) {
    const std::string head = "  <node id=\"" + std::to_string(id) + "\" visible=\"true\" lat=\"" +
                             Fixed(position.lat_deg, 10) + "\" lon=\"" +
                             Fixed(position.lon_deg, 10) + "\"";
    return tags.empty() ? head + "/>\n" : head + ">\n" + tags + "  </node>\n";
  }

  GeoAnchor anchor_;
  int64_t next_id_ = -1;
  std::map<std::pair<int64_t, int64_t>, int64_t> ids_;
  std::string xml_;
};

std::string WayXml(int64_t id, const std::vector<int64_t>& nodes, const std::string& tags) {
  std::string xml = "  <way id=\"" + std::to_string(id) + "\" visible=\"true\">\n";
  for (const int64_t node : nodes) xml += "    <nd ref=\"" + std::to_string(node) + "\"/>\n";
  return xml + tags + "  </way>\n";
}

}  // namespace

void CheckGeoAnchor(const GeoAnchor& anchor) {
  if (!(anchor.lat_deg >= -89 && anchor.lat_deg <= 89)) {  // NaN fails
    throw OptionsError("--anchor-lat must be a latitude in [-89, 89] degrees, got " +
                       Fixed(anchor.lat_deg, 6));
  }
  if (!(anchor.lon_deg >= -180 && anchor.lon_deg <= 180)) {
    throw OptionsError("--anchor-lon must be a longitude in [-180, 180] degrees, got " +
                       Fixed(anchor.lon_deg, 6));
  }
}

LatLon MetresToLatLon(const GeoAnchor& anchor, double x_m, double y_m) {
  const double lat0_rad = anchor.lat_deg / kDegreesPerRadian;
  return {anchor.lat_deg + y_m / kEarthRadiusM * kDegreesPerRadian,
          anchor.lon_deg + x_m / (kEarthRadiusM * std::cos(lat0_rad)) * kDegreesPerRadian};
}

std::string AreaGraphToOsmAg(const proto::AreaGraph& graph, const std::string& map_name,
                             const GeoAnchor& anchor) {
  OsmNodeTable nodes(anchor);
  nodes.AddRoot(map_name);
  std::vector<std::vector<int64_t>> area_nodes;
  for (const proto::Area& area : graph.areas()) {
    const proto::Polygon polygon = AreaPolygonMetres(graph, area);
    if (polygon.outer().points_size() < 3) {
      throw InputError(AreaName(area.id()) +
                       " has fewer than 3 vertices; cannot write it to osmAG");
    }
    std::vector<int64_t> ring;
    for (const proto::Point2& point : OrientedRing(polygon.outer(), true)) {
      ring.push_back(nodes.NodeAt(point.x(), point.y()));
    }
    ring.push_back(ring.front());
    area_nodes.push_back(std::move(ring));
  }
  std::vector<std::vector<int64_t>> passage_nodes;
  for (const proto::Passage& passage : graph.passages()) {
    const proto::Segment& segment = passage.segment_m();
    passage_nodes.push_back({nodes.NodeAt(segment.a().x(), segment.a().y()),
                             nodes.NodeAt(segment.b().x(), segment.b().y())});
  }

  std::string ways;
  for (int i = 0; i < graph.areas_size(); ++i) {
    const proto::Area& area = graph.areas(i);
    ways +=
        WayXml(nodes.NextId(), area_nodes[i],
               Tag("indoor", "room") + Tag("name", AreaName(area.id())) +
                   Tag("osmAG:areaType", AreaKindName(area.kind())) + Tag("osmAG:type", "area"));
  }
  for (int i = 0; i < graph.passages_size(); ++i) {
    const proto::Passage& passage = graph.passages(i);
    ways += WayXml(nodes.NextId(), passage_nodes[i],
                   Tag("name", "passage_" + std::to_string(passage.id())) +
                       Tag("osmAG:from", AreaName(passage.area_a())) +
                       Tag("osmAG:to", AreaName(passage.area_b())) + Tag("osmAG:type", "passage") +
                       Tag("width", Metres(passage.width_m())));
  }
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<osm version=\"0.6\" generator=\"areagraph\">\n" +
         nodes.xml() + ways + "</osm>\n";
}

}  // namespace areagraph
