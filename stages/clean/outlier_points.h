#pragma once

#include <Eigen/Core>
#include <vector>

namespace areagraph {

// CGAL's remove_outliers on 2D points (lifted to z = 0): each point's score is
// its mean squared distance to its k + 1 nearest points, itself included
// (CGAL 5.5 asks its kd-tree for k + 1 points, the query point first). The
// result lists, in increasing order, the indices of the at most `percent` % of
// points with the largest scores, keeping every point whose score is below
// min_score (CGAL's threshold_distance, squared).
std::vector<int> FindOutlierPoints(const std::vector<Eigen::Vector2d>& points, int k,
                                   double percent, double min_score);

}  // namespace areagraph
