#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/geometry/edge_polygon.h"

namespace areagraph {

// A vertex of the graph being pruned: a Voronoi vertex that is (or may
// become) a dead end or a junction.
struct ChainVertex {
  Eigen::Vector2d position;
  double clearance_px = 0;
  // Set on one vertex of a pure cycle, which has no vertex of degree != 2.
  bool forced_junction = false;
};

// A chain of Voronoi edges between two vertices, with the sites of the faces
// on either side of each segment (oriented from source to target) and the
// polygons of the dead ends it absorbed.
struct ChainEdge {
  int source = -1;
  int target = -1;
  PointList path;
  PointList left_sites;
  PointList right_sites;
  std::vector<double> clearance_px;
  // Smallest clearance of the Voronoi edges along the chain.
  double min_clearance_px = 0;
  std::vector<proto::Polygon> absorbed;
  bool removed = false;

  double Length() const { return PathLength(path); }
  // The same chain walked from target to source.
  ChainEdge Reversed() const;
  // Turns this chain around in place (what Reversed returns).
  void Reverse();
  // Appends `next`, which must start where this chain ends; from a chain
  // that is given up, its absorbed polygons are moved, not copied.
  void Append(const ChainEdge& next);
  void Append(ChainEdge&& next);
  // The edge's own polygon followed by everything it absorbed, which it
  // gives up (moved, not copied: for an edge that is being removed).
  std::vector<proto::Polygon> TakeAllPolygons();
};

// One end of an edge at a vertex: which edge, and whether it is the edge's
// target end. A self-loop has two incidences at its vertex.
struct Incidence {
  int edge = -1;
  bool at_target = false;
};

// One Voronoi edge between two chain vertices, before chains are joined:
// the sites on its left and right (indices into a site list) and its
// clearance.
struct ChainSegment {
  int source = -1;
  int target = -1;
  int left_site = -1;
  int right_site = -1;
  double clearance_px = 0;
};

// What ChainGraph::KeepParts kept and dropped.
struct PartSelection {
  // Groups kept: one per part of the free space kept, plus the long groups
  // kept beside a longer one in their part.
  int kept = 0;
  // Parts whose groups were all dropped for the part's size, and their cells.
  int dropped = 0;
  int64_t dropped_cells = 0;
};

// The multigraph of chains that ag-prune reduces to the Topology Graph.
class ChainGraph {
 public:
  std::vector<ChainVertex> vertices;
  std::vector<ChainEdge> edges;

  // The live edge ends at each vertex.
  std::vector<std::vector<Incidence>> Incidences() const;

  // Replaces every maximal path through vertices of degree 2 by one edge.
  // Pure cycles get one vertex marked as a forced junction.
  void JoinDegreeTwoChains();
  // Sets `edges` to what JoinDegreeTwoChains makes of one one-segment edge
  // per segment (path: its two vertices' positions; clearances: theirs; one
  // site a side), without building those edges first. `vertices` must be set.
  void JoinSegments(const std::vector<ChainSegment>& segments, const PointList& sites);

  // Keeps the connected group with the largest total edge length (the
  // paper's keepBiggestGroup) and, in every other part of the free space
  // with at least `min_cells` cells, the longest group there; removes the
  // edges of the rest. `part_of` gives a vertex's part (-1: none) and
  // `part_cells` each part's size: a group belongs to the part of most of
  // its vertices. Groups in a part that has a longer one are dropped as the
  // paper drops them (their cells are left to the part's areas' growth),
  // unless their edges are at least `min_group_length_px` long in total
  // (0: never; prune.keep_groups_above_m).
  PartSelection KeepParts(const std::function<int(int vertex)>& part_of,
                          const std::vector<int64_t>& part_cells, int64_t min_cells,
                          double min_group_length_px = 0);

  // Drops removed edges (edge indices change; vertex indices do not).
  void CompactEdges();
};

// Direction in which the edge end `incidence` leaves its vertex, as an angle
// in pixel coordinates (growing clockwise on screen).
double LeavingAngle(const ChainEdge& edge, bool at_target);

}  // namespace areagraph
