#include "tools/export/geojson_export.h"

#include <cmath>
#include <vector>

#include "common/error.h"
#include "tools/export/area_polygons.h"
#include "tools/export/json_text.h"

namespace areagraph {

namespace {

std::string Position(const proto::Point2& point) {
  return "[" + JsonNumber(point.x()) + "," + JsonNumber(point.y()) + "]";
}

// A closed ring: the first position repeated at the end.
std::string ClosedRing(const proto::Ring& ring, bool counter_clockwise) {
  const std::vector<proto::Point2> points = OrientedRing(ring, counter_clockwise);
  std::string text = "[";
  for (const proto::Point2& point : points) text += Position(point) + ",";
  return text + Position(points.front()) + "]";
}

std::string AreaGeometry(const proto::Polygon& polygon) {
  if (polygon.outer().points_size() < 3) return "null";
  std::string rings = ClosedRing(polygon.outer(), true);
  for (const proto::Ring& hole : polygon.holes()) {
    if (hole.points_size() >= 3) rings += "," + ClosedRing(hole, false);
  }
  return "{\"type\":\"Polygon\",\"coordinates\":[" + rings + "]}";
}

std::string AreaFeature(const proto::AreaGraph& graph, const proto::Area& area) {
  const proto::Polygon polygon = AreaPolygonMetres(graph, area);
  RequireFiniteVertices(polygon, AreaName(area.id()));
  return "{\"type\":\"Feature\",\"geometry\":" + AreaGeometry(polygon) +
         ",\"properties\":{\"id\":" + std::to_string(area.id()) +
         ",\"kind\":" + JsonString(AreaKindName(area.kind())) +
         ",\"area_m2\":" + JsonNumber(area.area_m2()) +
         ",\"name\":" + JsonString(AreaName(area.id())) + "}}";
}

// The passage as a line: the border its areas share (whose points are
// vertices of both area polygons), or the segment across the opening.
std::string PassageFeature(const proto::Passage& passage) {
  std::vector<proto::Point2> line(passage.border_m().begin(), passage.border_m().end());
  if (line.size() < 2) line = {passage.segment_m().a(), passage.segment_m().b()};
  std::string coordinates;
  for (const proto::Point2& point : line) {
    if (!std::isfinite(point.x()) || !std::isfinite(point.y()) ||
        !std::isfinite(passage.width_m())) {
      throw InputError("passage " + std::to_string(passage.id()) +
                       " has a coordinate that is not a finite number");
    }
    coordinates += (coordinates.empty() ? "" : ",") + Position(point);
  }
  return "{\"type\":\"Feature\",\"geometry\":{\"type\":\"LineString\",\"coordinates\":[" +
         coordinates + "]},\"properties\":{\"id\":" + std::to_string(passage.id()) +
         ",\"kind\":\"passage\",\"width_m\":" + JsonNumber(passage.width_m()) +
         ",\"from\":" + std::to_string(passage.area_a()) +
         ",\"to\":" + std::to_string(passage.area_b()) + "}}";
}

}  // namespace

std::string AreaGraphToGeoJson(const proto::AreaGraph& graph) {
  std::vector<std::string> features;
  for (const proto::Area& area : graph.areas()) features.push_back(AreaFeature(graph, area));
  for (const proto::Passage& passage : graph.passages()) {
    features.push_back(PassageFeature(passage));
  }
  std::string text = "{\"type\":\"FeatureCollection\",\"features\":[\n";
  for (size_t i = 0; i < features.size(); ++i) {
    text += features[i] + (i + 1 < features.size() ? ",\n" : "\n");
  }
  return text + "]}\n";
}

}  // namespace areagraph
