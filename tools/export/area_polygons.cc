#include "tools/export/area_polygons.h"

#include <algorithm>
#include <cmath>

#include "common/error.h"
#include "stages/common/map_frame.h"
#include "stages/geometry/ring_area.h"

namespace areagraph {

namespace {

// Applies `convert` (Eigen point -> Eigen point) to every vertex.
template <typename Convert>
proto::Polygon ConvertPolygon(const proto::Polygon& polygon, Convert convert) {
  auto convert_ring = [&](const proto::Ring& ring, proto::Ring* out) {
    for (const proto::Point2& point : ring.points()) {
      const Eigen::Vector2d converted = convert(Eigen::Vector2d(point.x(), point.y()));
      proto::Point2* added = out->add_points();
      added->set_x(converted.x());
      added->set_y(converted.y());
    }
  };
  proto::Polygon result;
  convert_ring(polygon.outer(), result.mutable_outer());
  for (const proto::Ring& hole : polygon.holes()) convert_ring(hole, result.add_holes());
  return result;
}

}  // namespace

proto::Polygon AreaPolygonMetres(const proto::AreaGraph& graph, const proto::Area& area) {
  if (area.polygon_m().outer().points_size() > 0 || area.polygon_px().outer().points_size() == 0) {
    return area.polygon_m();
  }
  const MapTransform transform(graph.frame());
  return ConvertPolygon(area.polygon_px(),
                        [&](const Eigen::Vector2d& p) { return transform.PixelToWorld(p); });
}

proto::Polygon AreaPolygonPixels(const proto::AreaGraph& graph, const proto::Area& area) {
  if (area.polygon_px().outer().points_size() > 0 || area.polygon_m().outer().points_size() == 0) {
    return area.polygon_px();
  }
  const MapTransform transform(graph.frame());
  return ConvertPolygon(area.polygon_m(),
                        [&](const Eigen::Vector2d& p) { return transform.WorldToPixel(p); });
}

std::vector<proto::Point2> OrientedRing(const proto::Ring& ring, bool counter_clockwise) {
  std::vector<proto::Point2> points(ring.points().begin(), ring.points().end());
  if ((TwiceSignedArea(ring) > 0) != counter_clockwise) std::reverse(points.begin(), points.end());
  return points;
}

void RequireFiniteVertices(const proto::Polygon& polygon, const std::string& what) {
  auto check = [&](const proto::Ring& ring) {
    for (const proto::Point2& point : ring.points()) {
      if (!std::isfinite(point.x()) || !std::isfinite(point.y())) {
        throw InputError(what + " has a vertex that is not a finite number");
      }
    }
  };
  check(polygon.outer());
  for (const proto::Ring& hole : polygon.holes()) check(hole);
}

std::string AreaKindName(proto::AreaKind kind) {
  switch (kind) {
    case proto::AREA_ROOM:
      return "room";
    case proto::AREA_CORRIDOR:
      return "corridor";
    case proto::AREA_DEAD_END:
      return "dead_end";
  }
  return "room";
}

std::string AreaName(int id) { return "area_" + std::to_string(id); }

std::vector<proto::Point2> PassageLine(const proto::Passage& passage) {
  std::vector<proto::Point2> line(passage.border_m().begin(), passage.border_m().end());
  if (line.size() < 2) line = {passage.segment_m().a(), passage.segment_m().b()};
  for (const proto::Point2& point : line) {
    if (!std::isfinite(point.x()) || !std::isfinite(point.y()) ||
        !std::isfinite(passage.width_m())) {
      throw InputError("passage " + std::to_string(passage.id()) +
                       " has a coordinate that is not a finite number");
    }
  }
  return line;
}

}  // namespace areagraph
