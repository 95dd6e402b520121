#include "tools/export/node_link_json.h"

#include <cmath>
#include <vector>

#include "common/error.h"
#include "tools/export/area_polygons.h"
#include "tools/export/export_ids.h"
#include "tools/export/json_text.h"

namespace areagraph {

namespace {

std::string Position(const proto::Point2& point) {
  if (!std::isfinite(point.x()) || !std::isfinite(point.y())) {
    throw InputError("the Area Graph has a coordinate that is not a finite number");
  }
  return "[" + JsonNumber(point.x(), kMetreDecimals) + "," + JsonNumber(point.y(), kMetreDecimals) +
         "]";
}

std::string Positions(const std::vector<proto::Point2>& points) {
  std::string text;
  for (const proto::Point2& point : points) text += (text.empty() ? "" : ",") + Position(point);
  return "[" + text + "]";
}

// ',"stable_id":N' for a graph with stable ids (ag-match's), else nothing;
// then the index in this version.
std::string StableIdAndIndex(const ExportIds& ids, int32_t stable_id, int32_t index) {
  return (ids.stable() ? ",\"stable_id\":" + std::to_string(stable_id) : "") +
         ",\"index\":" + std::to_string(index);
}

std::string Node(const proto::AreaGraph& graph, const ExportIds& ids, const proto::Area& area) {
  const proto::Polygon polygon = AreaPolygonMetres(graph, area);
  std::string holes;
  for (const proto::Ring& hole : polygon.holes()) {
    holes += (holes.empty() ? "" : ",") + Positions(OrientedRing(hole, false));
  }
  const int32_t id = ids.Of(area);
  return "{\"id\":" + std::to_string(id) + StableIdAndIndex(ids, area.stable_id(), area.id()) +
         ",\"name\":" + JsonString(AreaName(id)) +
         ",\"kind\":" + JsonString(AreaKindName(area.kind())) +
         ",\"area_m2\":" + JsonNumber(area.area_m2(), kMetreDecimals) +
         ",\"centroid\":" + Position(area.centroid_m()) +
         ",\"polygon\":" + Positions(OrientedRing(polygon.outer(), true)) + ",\"holes\":[" + holes +
         "]}";
}

std::string Link(const ExportIds& ids, const proto::Passage& passage) {
  const std::string id = std::to_string(ids.Of(passage));
  return "{\"source\":" + std::to_string(ids.OfArea(passage.area_a())) +
         ",\"target\":" + std::to_string(ids.OfArea(passage.area_b())) + ",\"key\":" + id +
         ",\"id\":" + id + StableIdAndIndex(ids, passage.stable_id(), passage.id()) +
         ",\"name\":\"passage_" + id +
         "\",\"width_m\":" + JsonNumber(passage.width_m(), kMetreDecimals) +
         ",\"point\":" + Position(passage.point_m()) +
         ",\"border\":" + Positions(PassageLine(passage)) + "}";
}

}  // namespace

std::string AreaGraphToNodeLinkJson(const proto::AreaGraph& graph, const std::string& map_name) {
  const ExportIds ids(graph);
  std::vector<std::string> nodes, links;
  for (const proto::Area& area : graph.areas()) nodes.push_back(Node(graph, ids, area));
  for (const proto::Passage& passage : graph.passages()) links.push_back(Link(ids, passage));
  return "{\"directed\":false,\"multigraph\":true,\"graph\":{\"name\":" + JsonString(map_name) +
         ",\"ids\":" + JsonString(IdsKindName(ids)) +
         (graph.has_version() ? ",\"version\":" + std::to_string(graph.version().number()) : "") +
         ",\"frame\":" + MessageJson(graph.frame()) +
         ",\"units\":\"metres\"},\n\"nodes\":" + JsonLines(nodes) +
         ",\n\"links\":" + JsonLines(links) + ",\n\"edges\":" + JsonLines(links) + "}\n";
}

}  // namespace areagraph
