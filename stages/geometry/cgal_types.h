#pragma once

// CGAL types shared by the geometry code. This header pulls in heavy CGAL
// templates: include it only from the few .cc files that run CGAL, never from
// a header, so that the rest of the project compiles quickly.

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <Eigen/Core>
#include <utility>
#include <vector>

namespace areagraph::cgal {

// Exact predicates keep the triangulation of the (very degenerate) pixel grid
// consistent; constructions such as circumcentres are plain doubles.
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;

// Delaunay triangulation whose vertices carry their index in the site list
// and whose faces carry an int for the caller (for example a Voronoi vertex id).
using SiteVertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using SiteFaceBase = CGAL::Triangulation_face_base_with_info_2<int, Kernel>;
using SiteTds = CGAL::Triangulation_data_structure_2<SiteVertexBase, SiteFaceBase>;
using SiteDelaunay = CGAL::Delaunay_triangulation_2<Kernel, SiteTds>;

inline Point ToCgal(const Eigen::Vector2d& p) { return Point(p.x(), p.y()); }
inline Eigen::Vector2d ToEigen(const Point& p) { return {p.x(), p.y()}; }

// Points paired with their index, the input CGAL's spatially sorted range
// insertion wants for triangulations with vertex info.
inline std::vector<std::pair<Point, int>> IndexedPoints(
    const std::vector<Eigen::Vector2d>& points) {
  std::vector<std::pair<Point, int>> indexed;
  indexed.reserve(points.size());
  for (size_t i = 0; i < points.size(); ++i) indexed.emplace_back(ToCgal(points[i]), int(i));
  return indexed;
}

}  // namespace areagraph::cgal
