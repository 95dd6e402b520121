#include "tools/export/osmag_export.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

#include "common/error.h"
#include "tools/export/area_polygons.h"
#include "tools/export/osm_xml.h"

namespace areagraph {

namespace {

// How far the structure area lies outside the areas' bounding box.
constexpr double kStructureMarginM = 0.1;

std::string Metres(double value) { return FixedDecimals(value, 3); }

// The id that stays across the map's versions (ag-match), for a graph that
// has them; a merge artifact's indices are not stable, so they get none.
std::string StableIdTag(const proto::AreaGraph& graph, int32_t stable_id) {
  if (!graph.has_version()) return "";
  return OsmTag("areagraph:stable_id", std::to_string(stable_id));
}

double SquaredDistanceToSegment(const proto::Point2& p, const proto::Point2& a,
                                const proto::Point2& b) {
  const double dx = b.x() - a.x(), dy = b.y() - a.y(), length2 = dx * dx + dy * dy;
  const double t =
      length2 > 0 ? std::clamp(((p.x() - a.x()) * dx + (p.y() - a.y()) * dy) / length2, 0.0, 1.0)
                  : 0.0;
  const double ex = a.x() + t * dx - p.x(), ey = a.y() + t * dy - p.y();
  return ex * ex + ey * ey;
}

// Puts `point` into the closed ring `ring` (first point not repeated) on its
// nearest edge, unless it already is a vertex (to the micrometre, as nodes).
void InsertIntoRing(const proto::Point2& point, std::vector<proto::Point2>* ring) {
  size_t best = 0;
  double best_distance = INFINITY;
  for (size_t i = 0; i < ring->size(); ++i) {
    const proto::Point2& a = (*ring)[i];
    if (std::abs(a.x() - point.x()) < 1e-6 && std::abs(a.y() - point.y()) < 1e-6) return;
    const double distance = SquaredDistanceToSegment(point, a, (*ring)[(i + 1) % ring->size()]);
    if (distance < best_distance) best_distance = distance, best = i;
  }
  ring->insert(ring->begin() + static_cast<std::ptrdiff_t>(best) + 1, point);
}

// Every area's outer ring in metres, counter-clockwise, with every point of
// its passages' lines made a vertex (they already are when the graph keeps
// the partition contract of border_m).
std::vector<std::vector<proto::Point2>> AreaRings(const proto::AreaGraph& graph) {
  std::vector<std::vector<proto::Point2>> rings;
  std::map<int, size_t> index_of_id;
  for (const proto::Area& area : graph.areas()) {
    const proto::Polygon polygon = AreaPolygonMetres(graph, area);
    if (polygon.outer().points_size() < 3) {
      throw InputError(AreaName(area.id()) +
                       " has fewer than 3 vertices; cannot write it to osmAG");
    }
    index_of_id[area.id()] = rings.size();
    rings.push_back(OrientedRing(polygon.outer(), true));
  }
  for (const proto::Passage& passage : graph.passages()) {
    for (const int id : {passage.area_a(), passage.area_b()}) {
      const auto found = index_of_id.find(id);
      if (found == index_of_id.end()) continue;
      for (const proto::Point2& end : PassageLine(passage))
        InsertIntoRing(end, &rings[found->second]);
    }
  }
  return rings;
}

// A closed way around all rings, kStructureMarginM outside their bounding box.
std::vector<int64_t> StructureOutline(const std::vector<std::vector<proto::Point2>>& rings,
                                      OsmNodeTable* nodes) {
  double min_x = INFINITY, min_y = INFINITY, max_x = -INFINITY, max_y = -INFINITY;
  for (const auto& ring : rings) {
    for (const proto::Point2& p : ring) {
      min_x = std::min(min_x, p.x()), max_x = std::max(max_x, p.x());
      min_y = std::min(min_y, p.y()), max_y = std::max(max_y, p.y());
    }
  }
  if (rings.empty()) min_x = min_y = max_x = max_y = 0;
  min_x -= kStructureMarginM, min_y -= kStructureMarginM;
  max_x += kStructureMarginM, max_y += kStructureMarginM;
  std::vector<int64_t> outline = {nodes->NodeAt(min_x, min_y), nodes->NodeAt(max_x, min_y),
                                  nodes->NodeAt(max_x, max_y), nodes->NodeAt(min_x, max_y)};
  outline.push_back(outline.front());
  return outline;
}

}  // namespace

std::string AreaGraphToOsmAg(const proto::AreaGraph& graph, const OsmAgSettings& settings) {
  OsmNodeTable nodes(settings.anchor);
  nodes.AddAnchorNode(OsmTag("name", "root") + OsmTag("osmAG:type", "root") +
                      OsmTag("osmAG:map", settings.map_name));
  const std::vector<std::vector<proto::Point2>> rings = AreaRings(graph);
  const std::string level = OsmTag("level", std::to_string(settings.level));
  const std::vector<int64_t> structure = StructureOutline(rings, &nodes);
  std::string ways =
      OsmWayXml(nodes.NextId(), structure,
                OsmTag("indoor", "level") + level + OsmTag("name", settings.map_name) +
                    OsmTag("osmAG:areaType", "structure") + OsmTag("osmAG:type", "area"));
  const std::string height =
      settings.height_m > 0 ? OsmTag("height", Metres(settings.height_m)) : std::string();
  for (int i = 0; i < graph.areas_size(); ++i) {
    const proto::Area& area = graph.areas(i);
    std::vector<int64_t> outline;
    for (const proto::Point2& p : rings[i]) outline.push_back(nodes.NodeAt(p.x(), p.y()));
    outline.push_back(outline.front());
    ways += OsmWayXml(nodes.NextId(), outline,
                      OsmTag("areagraph:kind", AreaKindName(area.kind())) +
                          StableIdTag(graph, area.stable_id()) + height + OsmTag("indoor", "room") +
                          level + OsmTag("name", AreaName(area.id())) +
                          OsmTag("osmAG:areaType", "room") +
                          OsmTag("osmAG:parent", settings.map_name) + OsmTag("osmAG:type", "area"));
  }
  for (const proto::Passage& passage : graph.passages()) {
    std::vector<int64_t> line;
    for (const proto::Point2& p : PassageLine(passage)) line.push_back(nodes.NodeAt(p.x(), p.y()));
    ways += OsmWayXml(
        nodes.NextId(), line,
        StableIdTag(graph, passage.stable_id()) + OsmTag("door", "yes") + OsmTag("indoor", "door") +
            level + OsmTag("name", "passage_" + std::to_string(passage.id())) +
            OsmTag("osmAG:from", AreaName(passage.area_a())) +
            OsmTag("osmAG:to", AreaName(passage.area_b())) + OsmTag("osmAG:type", "passage") +
            OsmTag("width", Metres(passage.width_m())));
  }
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<osm version=\"0.6\" generator=\"areagraph\" upload=\"never\">\n" +
         nodes.xml() + ways + "</osm>\n";
}

}  // namespace areagraph
