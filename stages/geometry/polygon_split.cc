// The one translation unit of the stages that compiles CGAL's Boolean set
// operations.
#include "stages/geometry/polygon_split.h"

#include <CGAL/Boolean_set_operations_2/Gps_polygon_validation.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Gps_segment_traits_2.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <iterator>
#include <list>
#include <utility>

#include "stages/geometry/ring_area.h"
#include "stages/geometry/ring_points.h"

namespace areagraph {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Polygon = CGAL::Polygon_2<Kernel>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;
using PolygonSet = CGAL::Polygon_set_2<Kernel>;  // Gps_segment_traits_2

// The ring as a CGAL polygon with the given orientation; false when it is
// not simple (CGAL's Boolean operations require simple rings).
bool ToPolygon(const proto::Ring& ring, CGAL::Orientation orientation, Polygon* out) {
  Polygon polygon;
  for (int i = 0; i < RingSize(ring); ++i) {
    const Eigen::Vector2d p = RingPoint(ring, i);
    const Kernel::Point_2 point(p.x(), p.y());
    if (polygon.is_empty() || *std::prev(polygon.vertices_end()) != point) polygon.push_back(point);
  }
  while (polygon.size() > 1 && *std::prev(polygon.vertices_end()) == *polygon.vertices_begin()) {
    polygon.erase(std::prev(polygon.vertices_end()));
  }
  if (polygon.size() < 3 || !polygon.is_simple()) return false;
  if (polygon.orientation() != orientation) polygon.reverse_orientation();
  *out = std::move(polygon);
  return true;
}

// Whether CGAL's Boolean operations take `polygon`: they may crash on
// anything else, and their own results are not always valid (a hole that
// touches the outer ring).
bool IsValid(const PolygonWithHoles& polygon) {
  return CGAL::is_valid_polygon_with_holes(polygon, CGAL::Gps_segment_traits_2<Kernel>());
}

// The polygon for CGAL's Boolean operations; false unless it is valid for
// them (simple rings, holes inside the outer ring and apart from it and
// from each other).
bool ToPolygonWithHoles(const proto::Polygon& polygon, PolygonWithHoles* out) {
  Polygon outer;
  if (!ToPolygon(polygon.outer(), CGAL::COUNTERCLOCKWISE, &outer)) return false;
  PolygonWithHoles result(outer);
  for (const proto::Ring& ring : polygon.holes()) {
    Polygon hole;
    if (!ToPolygon(ring, CGAL::CLOCKWISE, &hole)) return false;
    result.add_hole(hole);
  }
  if (!IsValid(result)) return false;
  *out = std::move(result);
  return true;
}

// The ring in doubles, turned to run like `outer_counterclockwise` says for
// an outer ring (holes the other way).
proto::Ring ToRing(Polygon polygon, bool counterclockwise) {
  if ((polygon.orientation() == CGAL::COUNTERCLOCKWISE) != counterclockwise) {
    polygon.reverse_orientation();
  }
  proto::Ring ring;
  for (const Kernel::Point_2& p : polygon.vertices()) {
    proto::Point2* point = ring.add_points();
    point->set_x(CGAL::to_double(p.x()));
    point->set_y(CGAL::to_double(p.y()));
  }
  return ring;
}

proto::Polygon ToProto(const PolygonWithHoles& polygon, bool outer_counterclockwise) {
  proto::Polygon out;
  *out.mutable_outer() = ToRing(polygon.outer_boundary(), outer_counterclockwise);
  for (const Polygon& hole : polygon.holes()) {
    *out.add_holes() = ToRing(hole, !outer_counterclockwise);
  }
  return out;
}

Kernel::FT AreaOf(const PolygonWithHoles& polygon) {
  Kernel::FT area = polygon.outer_boundary().area();
  for (const Polygon& hole : polygon.holes()) area += hole.area();  // holes run clockwise
  return area;
}

// The piece of largest area (the first of equal ones).
std::list<PolygonWithHoles>::const_iterator LargestOf(const std::list<PolygonWithHoles>& pieces) {
  auto largest = pieces.begin();
  for (auto it = pieces.begin(); it != pieces.end(); ++it) {
    if (AreaOf(*it) > AreaOf(*largest)) largest = it;
  }
  return largest;
}

std::list<PolygonWithHoles> PiecesOf(const PolygonSet& set) {
  std::list<PolygonWithHoles> pieces;
  set.polygons_with_holes(std::back_inserter(pieces));
  return pieces;
}

}  // namespace

bool SplitPolygonByGuide(const proto::Polygon& whole, const proto::Polygon& guide,
                         proto::Polygon* inside, proto::Polygon* rest) {
  PolygonWithHoles cut_whole, cut_guide;
  if (!ToPolygonWithHoles(whole, &cut_whole) || !ToPolygonWithHoles(guide, &cut_guide)) {
    return false;
  }
  // The largest piece of whole ∩ guide; the largest piece of what is left of
  // whole is the rest, and the inside is whole without it, so that the thin
  // slivers where the guide's border runs just inside whole's go with the
  // inside. Every operation runs on a Polygon_set_2 (segment traits, the
  // traits IsValid checks with) and every piece fed back in is checked.
  PolygonSet common(cut_whole);
  common.intersection(cut_guide);
  const std::list<PolygonWithHoles> common_pieces = PiecesOf(common);
  if (common_pieces.empty()) return false;
  const PolygonWithHoles& largest_common = *LargestOf(common_pieces);
  if (!IsValid(largest_common)) return false;
  PolygonSet outside(cut_whole);
  outside.difference(largest_common);
  const std::list<PolygonWithHoles> outside_pieces = PiecesOf(outside);
  if (outside_pieces.empty()) return false;
  const PolygonWithHoles& kept = *LargestOf(outside_pieces);
  if (!IsValid(kept)) return false;
  PolygonSet cut_off(cut_whole);
  cut_off.difference(kept);
  const std::list<PolygonWithHoles> inside_pieces = PiecesOf(cut_off);
  if (inside_pieces.size() != 1) return false;
  const bool counterclockwise = TwiceSignedArea(whole.outer()) >= 0;
  *inside = ToProto(inside_pieces.front(), counterclockwise);
  *rest = ToProto(kept, counterclockwise);
  return true;
}

}  // namespace areagraph
