#include "tools/export/geojson_export.h"

#include <cmath>
#include <vector>

#include "common/error.h"
#include "tools/export/area_polygons.h"
#include "tools/export/export_ids.h"
#include "tools/export/json_text.h"

namespace areagraph {

namespace {

// Writes positions in metres, or in WGS 84 degrees when there is an anchor.
class PositionWriter {
 public:
  explicit PositionWriter(const std::optional<GeoAnchor>& anchor) : anchor_(anchor) {}

  std::string operator()(const proto::Point2& point) const {
    if (!anchor_) {
      return "[" + JsonNumber(point.x(), kMetreDecimals) + "," +
             JsonNumber(point.y(), kMetreDecimals) + "]";
    }
    const LatLon position = MetresToLatLon(*anchor_, point.x(), point.y());
    return "[" + JsonNumber(position.lon_deg, kDegreeDecimals) + "," +
           JsonNumber(position.lat_deg, kDegreeDecimals) + "]";
  }

 private:
  std::optional<GeoAnchor> anchor_;
};

// The map frame as an engineering (local) CRS in WKT2.
constexpr char kLocalMetresWkt[] =
    "ENGCRS[\"areagraph map frame\",EDATUM[\"map origin\"],CS[Cartesian,2],"
    "AXIS[\"x\",east,ORDER[1],LENGTHUNIT[\"metre\",1]],"
    "AXIS[\"y\",north,ORDER[2],LENGTHUNIT[\"metre\",1]]]";

// A closed ring: the first position repeated at the end.
std::string ClosedRing(const proto::Ring& ring, bool counter_clockwise,
                       const PositionWriter& position) {
  const std::vector<proto::Point2> points = OrientedRing(ring, counter_clockwise);
  std::string text = "[";
  for (const proto::Point2& point : points) text += position(point) + ",";
  return text + position(points.front()) + "]";
}

std::string AreaGeometry(const proto::Polygon& polygon, const PositionWriter& position) {
  if (polygon.outer().points_size() < 3) return "null";
  std::string rings = ClosedRing(polygon.outer(), true, position);
  for (const proto::Ring& hole : polygon.holes()) {
    if (hole.points_size() >= 3) rings += "," + ClosedRing(hole, false, position);
  }
  return "{\"type\":\"Polygon\",\"coordinates\":[" + rings + "]}";
}

// ',"stable_id":N' for a graph from ag-match (ids kept across the map's
// versions), else nothing.
std::string StableIdProperty(const ExportIds& ids, int32_t stable_id) {
  return ids.stable() ? ",\"stable_id\":" + std::to_string(stable_id) : "";
}

std::string AreaFeature(const proto::AreaGraph& graph, const ExportIds& ids,
                        const proto::Area& area, const PositionWriter& position) {
  const proto::Polygon polygon = AreaPolygonMetres(graph, area);
  const int32_t area_id = ids.Of(area);
  RequireFiniteVertices(polygon, AreaName(area_id));
  const std::string id = std::to_string(area_id);
  return "{\"type\":\"Feature\",\"id\":\"area/" + id +
         "\",\"geometry\":" + AreaGeometry(polygon, position) +
         ",\"properties\":{\"layer\":\"area\",\"area_id\":" + id +
         StableIdProperty(ids, area.stable_id()) + ",\"index\":" + std::to_string(area.id()) +
         ",\"kind\":" + JsonString(AreaKindName(area.kind())) +
         ",\"area_m2\":" + JsonNumber(area.area_m2(), kMetreDecimals) +
         ",\"name\":" + JsonString(AreaName(area_id)) + "}}";
}

std::string PassageFeature(const ExportIds& ids, const proto::Passage& passage,
                           const PositionWriter& position) {
  const std::string id = std::to_string(ids.Of(passage));
  std::string coordinates;
  for (const proto::Point2& point : PassageLine(passage)) {
    coordinates += (coordinates.empty() ? "" : ",") + position(point);
  }
  return "{\"type\":\"Feature\",\"id\":\"passage/" + id +
         "\",\"geometry\":{\"type\":\"LineString\",\"coordinates\":[" + coordinates +
         "]},\"properties\":{\"layer\":\"passage\",\"passage_id\":" + id +
         StableIdProperty(ids, passage.stable_id()) + ",\"index\":" + std::to_string(passage.id()) +
         ",\"kind\":\"passage\",\"width_m\":" + JsonNumber(passage.width_m(), kMetreDecimals) +
         ",\"from\":" + std::to_string(ids.OfArea(passage.area_a())) +
         ",\"to\":" + std::to_string(ids.OfArea(passage.area_b())) + "}}";
}

// The top-level members that say what the numbers mean.
std::string Header(const proto::AreaGraph& graph, const ExportIds& ids,
                   const GeoJsonSettings& settings) {
  std::string header = "{\"type\":\"FeatureCollection\",\"name\":" + JsonString(settings.map_name) +
                       ",\"ids\":" + JsonString(IdsKindName(ids)) +
                       ",\"frame\":" + MessageJson(graph.frame());
  if (settings.anchor) {
    return header + ",\"units\":\"degrees\",\"coordinates\":" +
           JsonString(
               "WGS 84 longitude, latitude (RFC 7946): the map frame's origin placed at "
               "the anchor") +
           ",\"anchor\":{\"lat_deg\":" + JsonNumber(settings.anchor->lat_deg, kDegreeDecimals) +
           ",\"lon_deg\":" + JsonNumber(settings.anchor->lon_deg, kDegreeDecimals) + "},\n";
  }
  // GeoJSON 2008's crs member, which RFC 7946 dropped but GDAL and QGIS still
  // read: without it they would take the metres for degrees.
  return header +
         ",\"crs\":{\"type\":\"name\",\"properties\":{\"name\":" + JsonString(kLocalMetresWkt) +
         "}},\"units\":\"metres\",\"coordinates\":" +
         JsonString(
             "local map frame in metres (x east, y north), NOT WGS 84 degrees; "
             "ag-export --anchor-lat/--anchor-lon writes WGS 84") +
         ",\n";
}

}  // namespace

GeoJsonFeatures ParseGeoJsonFeatures(const std::string& name) {
  if (name == "all") return GeoJsonFeatures::kAll;
  if (name == "areas") return GeoJsonFeatures::kAreas;
  if (name == "passages") return GeoJsonFeatures::kPassages;
  throw OptionsError("unknown --features '" + name + "'; use all, areas or passages");
}

std::string AreaGraphToGeoJson(const proto::AreaGraph& graph, const GeoJsonSettings& settings) {
  const PositionWriter position(settings.anchor);
  const ExportIds ids(graph);
  std::vector<std::string> features;
  if (settings.features != GeoJsonFeatures::kPassages) {
    for (const proto::Area& area : graph.areas()) {
      features.push_back(AreaFeature(graph, ids, area, position));
    }
  }
  if (settings.features != GeoJsonFeatures::kAreas) {
    for (const proto::Passage& passage : graph.passages()) {
      features.push_back(PassageFeature(ids, passage, position));
    }
  }
  return Header(graph, ids, settings) + "\"features\":" + JsonLines(features) + "}\n";
}

}  // namespace areagraph
