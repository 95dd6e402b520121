#pragma once

#include <Eigen/Core>
#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/geometry/edge_polygon.h"

namespace areagraph {

// A place on an edge's path: `t` of the way along segment `segment`
// (path[segment] -> path[segment + 1]).
struct PathPosition {
  int segment = 0;
  double t = 0;
};

// An edge's path with arc lengths, for cutting it into pieces.
class EdgeTrack {
 public:
  explicit EdgeTrack(const proto::GraphEdge& edge);

  const proto::GraphEdge& edge() const { return *edge_; }
  const PointList& path() const { return path_; }
  int segment_count() const { return static_cast<int>(path_.size()) - 1; }
  double length() const { return arc_.back(); }

  PathPosition Start() const { return {0, 0}; }
  PathPosition End() const { return {segment_count() - 1, 1}; }
  PathPosition AtVertex(int index) const;
  // Puts positions at a segment's very end onto the next segment's start.
  PathPosition Normalized(PathPosition position) const;

  Eigen::Vector2d PointAt(const PathPosition& position) const;
  double ArcAt(const PathPosition& position) const;
  // Distance to the nearest site. Every point of a Voronoi edge is as far
  // from its left site as from its right one, which makes this exact.
  double ClearanceAt(const PathPosition& position) const;

  // The part of the edge between two positions: path, sites, clearances,
  // length, minimum clearance and polygons (absorbed polygons not included).
  proto::GraphEdge Piece(const PathPosition& begin, const PathPosition& end) const;

 private:
  const proto::GraphEdge* edge_;
  PointList path_;
  PointList left_sites_;
  PointList right_sites_;
  std::vector<double> arc_;
};

}  // namespace areagraph
