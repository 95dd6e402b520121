#include "tools/export/osmag_export.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "common/error.h"
#include "stages/geometry/ring_area.h"
#include "tools/export/area_polygons.h"
#include "tools/export/export_ids.h"
#include "tools/export/json_text.h"
#include "tools/export/osm_xml.h"

namespace areagraph {

namespace {

// How far the structure area lies outside the areas' bounding box.
constexpr double kStructureMarginM = 0.1;

std::string Metres(double value) { return FixedDecimals(value, kMetreDecimals); }

using Ring = std::vector<proto::Point2>;

// An area's rings in metres: the outer one counter-clockwise, the holes
// clockwise.
struct AreaRings {
  Ring outer;
  std::vector<Ring> holes;
};

double SquaredDistanceToSegment(const proto::Point2& p, const proto::Point2& a,
                                const proto::Point2& b) {
  const double dx = b.x() - a.x(), dy = b.y() - a.y(), length2 = dx * dx + dy * dy;
  const double t =
      length2 > 0 ? std::clamp(((p.x() - a.x()) * dx + (p.y() - a.y()) * dy) / length2, 0.0, 1.0)
                  : 0.0;
  const double ex = a.x() + t * dx - p.x(), ey = a.y() + t * dy - p.y();
  return ex * ex + ey * ey;
}

// How far from a ring's edge a passage's point may lie and still be put on it.
constexpr double kOnEdgeM = 1e-3;

// Puts `point` on the edge of whichever of the area's rings (outer or a hole)
// it lies on, unless it already is a vertex of one of them (to the
// micrometre). A passage on a hole's border thus joins that hole. A point on
// no edge (the end of a passage whose areas share no border, an obstacle
// beside the opening) is left out: it would bend the outline into the wall.
void InsertIntoRings(const proto::Point2& point, AreaRings* area) {
  std::vector<Ring*> rings = {&area->outer};
  for (Ring& hole : area->holes) rings.push_back(&hole);
  Ring* best_ring = nullptr;
  size_t best = 0;
  double best_distance = INFINITY;
  for (Ring* ring : rings) {
    for (size_t i = 0; i < ring->size(); ++i) {
      const proto::Point2& a = (*ring)[i];
      if (std::abs(a.x() - point.x()) < 1e-6 && std::abs(a.y() - point.y()) < 1e-6) return;
      const double distance = SquaredDistanceToSegment(point, a, (*ring)[(i + 1) % ring->size()]);
      if (distance < best_distance) best_distance = distance, best = i, best_ring = ring;
    }
  }
  if (best_distance > kOnEdgeM * kOnEdgeM) return;
  best_ring->insert(best_ring->begin() + static_cast<std::ptrdiff_t>(best) + 1, point);
}

// Every area's rings, with every point of its passages' lines that lies on
// one of them made a vertex of it (they already are when the graph keeps the
// partition contract of border_m). Holes of fewer than 3 points are dropped.
std::vector<AreaRings> RingsOfAreas(const proto::AreaGraph& graph, const ExportIds& ids) {
  std::vector<AreaRings> areas;
  std::map<int, size_t> index_of_id;
  for (const proto::Area& area : graph.areas()) {
    const proto::Polygon polygon = AreaPolygonMetres(graph, area);
    if (polygon.outer().points_size() < 3) {
      throw InputError(AreaName(ids.Of(area)) +
                       " has fewer than 3 vertices; cannot write it to osmAG");
    }
    index_of_id[area.id()] = areas.size();
    AreaRings rings{OrientedRing(polygon.outer(), true), {}};
    for (const proto::Ring& hole : polygon.holes()) {
      if (hole.points_size() >= 3) rings.holes.push_back(OrientedRing(hole, false));
    }
    areas.push_back(std::move(rings));
  }
  for (const proto::Passage& passage : graph.passages()) {
    for (const int id : {passage.area_a(), passage.area_b()}) {
      const auto found = index_of_id.find(id);
      if (found == index_of_id.end()) continue;
      for (const proto::Point2& end : PassageLine(passage)) {
        InsertIntoRings(end, &areas[found->second]);
      }
    }
  }
  return areas;
}

// World metres on OSM's grid, not yet rounded.
std::vector<GridPosition> GridPositionsOf(const Ring& points, const OsmNodeTable& nodes) {
  std::vector<GridPosition> positions;
  for (const proto::Point2& p : points) positions.push_back(nodes.GridPositionOf(p.x(), p.y()));
  return positions;
}

// The nodes of a line, without a node repeated next to itself.
std::vector<int64_t> NodesOf(const std::vector<GridPoint>& line, OsmNodeTable* nodes) {
  std::vector<int64_t> refs;
  for (const GridPoint& point : line) {
    const int64_t node = nodes->NodeAt(point);
    if (refs.empty() || refs.back() != node) refs.push_back(node);
  }
  return refs;
}

// A closed loop of nodes (the first repeated at the end) and which way it
// runs: counter-clockwise loops bound the area, clockwise ones are holes.
struct NodeLoop {
  std::vector<int64_t> nodes;
  bool counter_clockwise = true;
};

// Whether grid points run counter-clockwise (longitude east, latitude north),
// by the shoelace taken about the first point to keep the products small.
bool CounterClockwise(const std::vector<GridPoint>& points) {
  proto::Ring ring;
  for (const GridPoint& point : points) {
    proto::Point2* added = ring.add_points();
    added->set_x(static_cast<double>(point.first - points.front().first));
    added->set_y(static_cast<double>(point.second - points.front().second));
  }
  return TwiceSignedArea(ring) > 0;
}

// A snap-rounded ring as closed loops of nodes. Where the ring visits a node
// twice (a neck narrower than OSM's precision) it touches itself, which JOSM
// reports as a self-intersecting way and GIS tools as an invalid polygon; so
// it is cut there into simple loops that share the node, each an outer ring
// or a hole of the area by the way it runs (the area stays on its left).
// Loops of fewer than 3 nodes (a spike there and back) enclose nothing and
// are dropped.
std::vector<NodeLoop> NodeLoopsOf(const std::vector<GridPoint>& ring, OsmNodeTable* nodes) {
  std::vector<NodeLoop> loops;
  std::vector<GridPoint> path;
  std::map<GridPoint, size_t> position_on_path;
  // Cuts the path from `from` on off as a loop.
  auto close_loop = [&](size_t from) {
    const std::vector<GridPoint> loop(path.begin() + static_cast<std::ptrdiff_t>(from), path.end());
    if (loop.size() >= 3) {
      NodeLoop closed{NodesOf(loop, nodes), CounterClockwise(loop)};
      closed.nodes.push_back(closed.nodes.front());
      loops.push_back(std::move(closed));
    }
    for (const GridPoint& point : loop) position_on_path.erase(point);
    path.resize(from);
  };
  for (size_t i = 0; i <= ring.size(); ++i) {
    const GridPoint& point = ring[i % ring.size()];
    if (const auto seen = position_on_path.find(point); seen != position_on_path.end()) {
      close_loop(seen->second);
    }
    if (i == ring.size()) break;
    position_on_path[point] = path.size();
    path.push_back(point);
  }
  if (!path.empty()) close_loop(0);
  return loops;
}

// A closed way around all rings, kStructureMarginM outside their bounding box.
std::vector<int64_t> StructureOutline(const std::vector<AreaRings>& areas, OsmNodeTable* nodes) {
  double min_x = INFINITY, min_y = INFINITY, max_x = -INFINITY, max_y = -INFINITY;
  for (const AreaRings& area : areas) {
    for (const proto::Point2& p : area.outer) {
      min_x = std::min(min_x, p.x()), max_x = std::max(max_x, p.x());
      min_y = std::min(min_y, p.y()), max_y = std::max(max_y, p.y());
    }
  }
  if (areas.empty()) min_x = min_y = max_x = max_y = 0;
  min_x -= kStructureMarginM, min_y -= kStructureMarginM;
  max_x += kStructureMarginM, max_y += kStructureMarginM;
  std::vector<int64_t> outline = {nodes->NodeAt(min_x, min_y), nodes->NodeAt(max_x, min_y),
                                  nodes->NodeAt(max_x, max_y), nodes->NodeAt(min_x, max_y)};
  outline.push_back(outline.front());
  return outline;
}

// `areagraph:stable_id` for a graph with stable ids, then `areagraph:index`.
std::string IdTags(const ExportIds& ids, int32_t stable_id, int32_t index) {
  return OsmTag("areagraph:index", std::to_string(index)) +
         (ids.stable() ? OsmTag("areagraph:stable_id", std::to_string(stable_id)) : "");
}

}  // namespace

std::string AreaGraphToOsmAg(const proto::AreaGraph& graph, const OsmAgSettings& settings) {
  const ExportIds ids(graph);
  OsmNodeTable nodes(settings.anchor);
  nodes.AddAnchorNode(OsmTag("areagraph:ids", IdsKindName(ids)) + OsmTag("name", "root") +
                      OsmTag("osmAG:type", "root") + OsmTag("osmAG:map", settings.map_name));
  const std::vector<AreaRings> rings = RingsOfAreas(graph, ids);
  const std::string level = OsmTag("level", std::to_string(settings.level));
  const std::vector<int64_t> structure = StructureOutline(rings, &nodes);
  std::string ways =
      OsmWayXml(nodes.NextId(), structure,
                OsmTag("indoor", "level") + level + OsmTag("name", settings.map_name) +
                    OsmTag("osmAG:areaType", "structure") + OsmTag("osmAG:type", "area"));
  // Every ring on OSM's grid, snap-rounded together so that shared borders
  // stay shared and no ring comes to cross itself.
  std::vector<std::vector<GridPosition>> positions;
  for (const AreaRings& area : rings) {
    positions.push_back(GridPositionsOf(area.outer, nodes));
    for (const Ring& hole : area.holes) positions.push_back(GridPositionsOf(hole, nodes));
  }
  const SnapRounder snap(positions);
  size_t next_ring = 0;
  std::string relations;
  const std::string height =
      settings.height_m > 0 ? OsmTag("height", Metres(settings.height_m)) : std::string();
  for (int i = 0; i < graph.areas_size(); ++i) {
    const proto::Area& area = graph.areas(i);
    std::string tags = IdTags(ids, area.stable_id(), area.id()) +
                       OsmTag("areagraph:kind", AreaKindName(area.kind())) + height +
                       OsmTag("indoor", "room") + level + OsmTag("name", AreaName(ids.Of(area))) +
                       OsmTag("osmAG:areaType", "room") +
                       OsmTag("osmAG:parent", settings.map_name) + OsmTag("osmAG:type", "area");
    std::vector<NodeLoop> loops;
    for (size_t ring = 0; ring <= rings[i].holes.size(); ++ring) {
      for (NodeLoop& loop : NodeLoopsOf(snap.Ring(positions[next_ring++]), &nodes)) {
        loops.push_back(std::move(loop));
      }
    }
    if (loops.size() == 1 && loops.front().counter_clockwise) {
      ways += OsmWayXml(nodes.NextId(), loops.front().nodes, tags);
      continue;
    }
    // An area with holes (or of several loops) is OSM's multipolygon: the
    // relation carries the area's tags, its rings are untagged closed ways.
    std::vector<OsmWayMember> members;
    for (const NodeLoop& loop : loops) {
      members.push_back({nodes.NextId(), loop.counter_clockwise ? "outer" : "inner"});
      ways += OsmWayXml(members.back().way, loop.nodes, "");
    }
    relations += OsmRelationXml(nodes.NextId(), members, OsmTag("type", "multipolygon") + tags);
  }
  for (const proto::Passage& passage : graph.passages()) {
    const int32_t id = ids.Of(passage);
    // osmAG's passage tags, and the width under our own key: JOSM reads
    // indoor=door, door=* and width on a way as a misplaced door node.
    ways += OsmWayXml(nodes.NextId(),
                      NodesOf(snap.Line(GridPositionsOf(PassageLine(passage), nodes)), &nodes),
                      IdTags(ids, passage.stable_id(), passage.id()) +
                          OsmTag("areagraph:width", Metres(passage.width_m())) + level +
                          OsmTag("name", "passage_" + std::to_string(id)) +
                          OsmTag("osmAG:from", AreaName(ids.OfArea(passage.area_a()))) +
                          OsmTag("osmAG:to", AreaName(ids.OfArea(passage.area_b()))) +
                          OsmTag("osmAG:type", "passage"));
  }
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<osm version=\"0.6\" generator=\"areagraph\" upload=\"never\">\n" +
         nodes.xml() + ways + relations + "</osm>\n";
}

}  // namespace areagraph
