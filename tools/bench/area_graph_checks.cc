// The one translation unit that compiles CGAL's Boolean set operations.
#include "tools/bench/area_graph_checks.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <algorithm>

namespace areagraph {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Polygon = CGAL::Polygon_2<Kernel>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;

Polygon ToPolygon(const proto::Ring& ring, CGAL::Orientation orientation) {
  Polygon polygon;
  for (const proto::Point2& p : ring.points()) polygon.push_back(Kernel::Point_2(p.x(), p.y()));
  if (polygon.size() >= 3 && polygon.orientation() != orientation) polygon.reverse_orientation();
  return polygon;
}

PolygonWithHoles ToPolygonWithHoles(const proto::Polygon& polygon) {
  PolygonWithHoles result(ToPolygon(polygon.outer(), CGAL::COUNTERCLOCKWISE));
  for (const proto::Ring& hole : polygon.holes()) {
    result.add_hole(ToPolygon(hole, CGAL::CLOCKWISE));
  }
  return result;
}

struct Box {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  bool Meets(const Box& other) const {
    return x0 <= other.x1 && other.x0 <= x1 && y0 <= other.y1 && other.y0 <= y1;
  }
};

Box BoxOf(const proto::Ring& ring) {
  Box box;
  for (const proto::Point2& p : ring.points()) {
    box.x0 = std::min(box.x0, p.x()), box.x1 = std::max(box.x1, p.x());
    box.y0 = std::min(box.y0, p.y()), box.y1 = std::max(box.y1, p.y());
  }
  return box;
}

bool IsVertexOf(const proto::Polygon& polygon, const proto::Point2& point) {
  auto in_ring = [&](const proto::Ring& ring) {
    return std::any_of(ring.points().begin(), ring.points().end(), [&](const proto::Point2& p) {
      return p.x() == point.x() && p.y() == point.y();
    });
  };
  return in_ring(polygon.outer()) ||
         std::any_of(polygon.holes().begin(), polygon.holes().end(), in_ring);
}

}  // namespace

std::vector<std::pair<int, int>> OverlappingAreaPairs(const proto::AreaGraph& graph) {
  const int count = graph.areas_size();
  std::vector<Box> boxes;
  std::vector<PolygonWithHoles> polygons;
  for (const proto::Area& area : graph.areas()) {
    boxes.push_back(BoxOf(area.polygon_px().outer()));
    polygons.push_back(ToPolygonWithHoles(area.polygon_px()));
  }
  std::vector<std::pair<int, int>> pairs;
  for (int a = 0; a < count; ++a) {
    for (int b = a + 1; b < count; ++b) {
      if (boxes[a].Meets(boxes[b]) && CGAL::do_intersect(polygons[a], polygons[b])) {
        pairs.emplace_back(a, b);
      }
    }
  }
  return pairs;
}

bool PassageEndsOnBothOutlines(const proto::AreaGraph& graph, const proto::Passage& passage) {
  for (const int id : {passage.area_a(), passage.area_b()}) {
    if (id < 0 || id >= graph.areas_size()) return false;
    const proto::Polygon& polygon = graph.areas(id).polygon_m();
    if (!IsVertexOf(polygon, passage.segment_m().a()) ||
        !IsVertexOf(polygon, passage.segment_m().b())) {
      return false;
    }
  }
  return true;
}

}  // namespace areagraph
