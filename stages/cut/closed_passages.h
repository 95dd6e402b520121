#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/geometry/edge_polygon.h"

namespace areagraph {

// A passage point this close (metres) to a site that ag-cut added to close
// a door or a wall gap lies on that closed line. The sites are about one
// per pixel along the line and the cut lies where the edge crosses it (or
// at the narrowest point next to it), so a few cells are enough.
inline constexpr double kClosedPassageReachM = 0.15;

// The lines ag-cut closed on purpose (the sites of the cut passes
// CLOSE_WALL_DOORS and CLOSE_WALL_GAPS), bucketed in cells of the reach so that a
// query looks at 3 x 3 buckets.
class ClosedLines {
 public:
  ClosedLines(const PointList& closing_sites, double resolution_m);

  bool empty() const { return buckets_.empty(); }
  // Whether `p` (pixels) lies within kClosedPassageReachM of a closing site.
  bool Near(const Eigen::Vector2d& p) const;

 private:
  int64_t Key(double x, double y) const;

  double reach_px_;
  std::unordered_map<int64_t, std::vector<Eigen::Vector2d>> buckets_;
};

// Marks the passage points of `graph` that lie on a closed line, so that
// ag-merge's room joining does not join the two rooms again
// (PassagePoint.closed_by_cut).
void MarkClosedPassages(const ClosedLines& lines, proto::CutGraph* graph);

}  // namespace areagraph
