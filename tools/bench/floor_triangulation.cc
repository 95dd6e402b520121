#include "tools/bench/floor_triangulation.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace areagraph {

size_t TriangulateSites(const std::vector<Eigen::Vector2d>& sites) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<Kernel::Point_2> points;
  points.reserve(sites.size());
  for (const Eigen::Vector2d& site : sites) points.emplace_back(site.x(), site.y());
  const CGAL::Delaunay_triangulation_2<Kernel> triangulation(points.begin(), points.end());
  return triangulation.number_of_faces();
}

}  // namespace areagraph
