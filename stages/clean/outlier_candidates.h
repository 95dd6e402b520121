#pragma once

#include <vector>

#include "stages/clean/occupied_rows.h"

namespace areagraph {

// An occupied cell that CGAL's remove_outliers may count as an outlier.
struct OutlierCandidate {
  // Flat cell index.
  int cell = 0;
  // Its remove_outliers score (see FindOutlierCandidates), in square pixels.
  double score = 0;
  // The squared distance to the farthest of the nearest cells that score
  // averages over: every occupied cell that close belongs to its neighbourhood.
  int reach2 = 0;
};

// CGAL's remove_outliers scores a point by the mean squared distance to its
// nearest points: the point itself and `neighbors` more (CGAL 5.5 asks its
// kd-tree for neighbors + 1 points, the query point first), or to all points
// when there are fewer. On cell centres every squared distance is an integer,
// so visiting the occupancy grid in order of distance gives exactly the same
// sum, and the same double. This does that for every occupied cell and
// returns, in row-major order, those whose score is not below
// `threshold_score`: all others can never be outliers.
std::vector<OutlierCandidate> FindOutlierCandidates(const OccupiedRows& occupied, int neighbors,
                                                    double threshold_score);

}  // namespace areagraph
