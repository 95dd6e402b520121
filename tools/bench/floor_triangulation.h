#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

namespace areagraph {

// Inserts `sites` into a plain CGAL Delaunay_triangulation_2 (Epick, one
// range insert, which sorts the points spatially first) and returns its
// number of finite faces, so that the work cannot be optimised away. This is
// the least any Voronoi-based pipeline does with a map's obstacle sites.
size_t TriangulateSites(const std::vector<Eigen::Vector2d>& sites);

}  // namespace areagraph
