#pragma once

#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "proto/artifacts.pb.h"
#include "tools/route/cell_index.h"
#include "tools/route/outline.h"

namespace areagraph {

// An area on a route, and where the route enters it.
struct AreaVisit {
  int area = 0;
  Vec2 entry;
};

// The free space of an Area Graph as routes see it: the union of the area
// polygons (closed), crossed only through passages. Answers where a point
// is and whether a straight segment stays inside without crossing a wall.
class FreeSpace {
 public:
  // Throws InputError when an area has no polygon in metres or a
  // coordinate is not finite.
  explicit FreeSpace(const proto::AreaGraph& graph);

  // The area whose closed polygon holds `point` (within kRouteTolerance of
  // its outline counts), or -1.
  int AreaAt(const Vec2& point) const;

  // Whether the segment lies in the free space and crosses no wall, neither
  // through an edge nor through a vertex where walls meet on both sides.
  // `starts_inside` says that it leaves `from` into the free space (from a
  // point StrictlyInside, or from a vertex along a direction it LeavesInto):
  // then crossing no wall is enough, and the test skips locating its pieces.
  bool SegmentIsFree(const Vec2& from, const Vec2& to, bool starts_inside = false) const;

  // Whether `direction` from the outline vertex points into an area.
  bool LeavesInto(int vertex, const Vec2& direction) const;
  // Whether `point` lies inside an area, off every outline.
  bool StrictlyInside(const Vec2& point) const;

  // The nearest point of the free space within `max_distance` of `point`
  // (outside every area: a point on a wall), or nullopt.
  std::optional<Vec2> NearestPoint(const Vec2& point, double max_distance) const;

  // Appends the areas the segment runs through, in order, with the point
  // where it enters each, skipping an area equal to the last in `visits`.
  void AppendAreasAlong(const Vec2& from, const Vec2& to, std::vector<AreaVisit>* visits) const;

  // The outline vertex at exactly `point`, or -1.
  int VertexAt(const Vec2& point) const;

  // The area's rings, outer first, each with the area on its left.
  const std::vector<std::vector<Vec2>>& area_rings(int area) const { return area_rings_[area]; }
  const std::vector<OutlineVertex>& vertices() const { return vertices_; }
  const std::vector<OutlineEdge>& edges() const { return edges_; }
  int area_count() const { return static_cast<int>(area_rings_.size()); }

 private:
  // Each area's rings, outer first, running with the area on their left.
  std::vector<std::vector<std::vector<Vec2>>> area_rings_;
  std::vector<Eigen::AlignedBox2d> area_boxes_;
  std::vector<OutlineVertex> vertices_;
  std::map<std::pair<double, double>, int> vertex_ids_;
  std::vector<OutlineEdge> edges_;
  CellIndex edge_cells_;
  CellIndex wall_cells_;
  CellIndex area_cells_;

  bool InsideArea(int area, const Vec2& point) const;
  // Where along a segment (t in (0, 1)) it meets an outline vertex, or
  // crosses an edge (vertex -1).
  struct Contact {
    double t;
    int vertex;
  };
  // The segment's contacts with the walls (`walls_only`: false as soon as it
  // crosses one) or with every outline edge, unordered.
  bool Contacts(const Vec2& from, const Vec2& to, bool walls_only,
                std::vector<Contact>* contacts) const;
  // Whether the segment passes the wall vertices it meets (`contacts`, in
  // order) without crossing a wall: off the walls' lines no walls on both of
  // its sides, and along a wall the same side clear all the way.
  bool WallsLetThrough(const Vec2& from, const Vec2& to,
                       const std::vector<Contact>& contacts) const;
};

}  // namespace areagraph
