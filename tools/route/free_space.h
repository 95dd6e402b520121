#pragma once

#include <Eigen/Core>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "proto/artifacts.pb.h"
#include "tools/route/cell_index.h"

namespace areagraph {

using Vec2 = Eigen::Vector2d;

// Distances below this (metres) count as zero: the areas share their border
// vertices bit for bit, so only rounding in the tests needs it.
constexpr double kRouteTolerance = 1e-7;

// One edge of an area's outline. A wall unless it lies on a passage's border
// (passage.border_m): two areas that touch elsewhere are apart.
struct OutlineEdge {
  Vec2 a, b;
  int area = 0;                    // index into AreaGraph.areas
  int vertex_a = 0, vertex_b = 0;  // indices into FreeSpace::vertices()
  bool wall = true;
};

// One corner of an area's outline, where the area's inside spans the angle
// from the direction of `next` counter-clockwise to that of `previous`.
struct CornerWedge {
  int area = 0;
  int next = 0, previous = 0;  // vertex indices
  double angle = 0;            // radians, in (0, 2 pi]
  bool next_is_wall = true, previous_is_wall = true;
};

// A point where outline edges meet, with what meets there.
struct OutlineVertex {
  Vec2 at;
  std::vector<Vec2> wall_directions;  // towards the other end of each wall from here
  std::vector<CornerWedge> wedges;
};

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
  bool SegmentIsFree(const Vec2& from, const Vec2& to) const;

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
  CellIndex area_cells_;

  bool InsideArea(int area, const Vec2& point) const;
  // Parameters in (0, 1) where the segment meets outline edges (walls only,
  // or every edge); false as soon as it crosses a wall when `walls_only`.
  bool Contacts(const Vec2& from, const Vec2& to, bool walls_only,
                std::vector<double>* contacts) const;
};

}  // namespace areagraph
