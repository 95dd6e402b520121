#pragma once

#include <Eigen/Core>
#include <vector>

#include "proto/artifacts.pb.h"

namespace areagraph {

// A passage between two areas, in pixel coordinates.
struct PassagePlan {
  int area_a = -1;
  int area_b = -1;
  // The graph vertex where the two areas meet.
  Eigen::Vector2d point;
  // Across the opening: the sites on either side of the edge at the vertex.
  Eigen::Vector2d side_a;
  Eigen::Vector2d side_b;
  double width_px = 0;
};

// Areas meet where their edges share a vertex: at a passage point, or at a
// junction (one passage for every pair of areas there). The opening is the
// narrower of the two areas' edge ends at the vertex, measured between the
// sites left and right of the edge. Passages of one pair of areas closer than
// half the wider opening are one passage (the narrower one is kept).
// `area_of_edge` gives each CutGraph edge's area (-1: none).
std::vector<PassagePlan> FindPassages(const proto::CutGraph& graph,
                                      const std::vector<int>& area_of_edge);

}  // namespace areagraph
