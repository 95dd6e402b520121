#pragma once

#include <Eigen/Core>
#include <vector>

namespace areagraph {

// One edge of an alpha shape's boundary, as indices into the point list.
struct AlphaShapeEdge {
  int a = 0;
  int b = 0;
  // Singular edges are one-dimensional pieces of the shape (no interior on
  // either side); their orientation means nothing. Regular edges are oriented
  // with the shape's interior on their left in pixel coordinates (y down),
  // that is cross(b - a, x - a) < 0 for an interior point x.
  bool singular = false;
};

// The alpha complex of a point set for one alpha, in CGAL's GENERAL mode:
// isolated points and one-dimensional pieces belong to the shape too.
struct AlphaComplex {
  // Connected component of each point. Points are connected when an edge of
  // the complex joins them; an isolated point is a component of its own.
  std::vector<int> component_of_point;
  int component_count = 0;
  // The regular and singular edges of the complex.
  std::vector<AlphaShapeEdge> boundary_edges;
};

// Alpha complex of `points` for a disk radius `alpha_radius` (CGAL's alpha is
// its square). Two points closer than 2 * alpha_radius with an empty circle of
// that radius through them end up in the same component.
AlphaComplex ComputeAlphaComplex(const std::vector<Eigen::Vector2d>& points, double alpha_radius);

// The boundary length of each component: regular edges count once, singular
// edges twice (a thin piece has two sides), isolated points zero.
std::vector<double> ComponentPerimeters(const std::vector<Eigen::Vector2d>& points,
                                        const AlphaComplex& complex);

}  // namespace areagraph
