#pragma once

#include <Eigen/Core>
#include <vector>

namespace areagraph {

// CGAL's remove_outliers on 2D points (lifted to z = 0): each point's score is
// its mean squared distance to its k nearest points (itself included). The
// result lists, in increasing order, the indices of the at most `percent` % of
// points with the largest scores, keeping every point whose score is at most
// min_score (CGAL's threshold_distance, squared).
std::vector<int> FindOutlierPoints(const std::vector<Eigen::Vector2d>& points, int k,
                                   double percent, double min_score);

}  // namespace areagraph
