#include "stages/geometry/alpha_shape.h"

#include <CGAL/Alpha_shape_2.h>
#include <CGAL/Alpha_shape_face_base_2.h>
#include <CGAL/Alpha_shape_vertex_base_2.h>

#include <numeric>

#include "stages/geometry/cgal_types.h"
#include "stages/geometry/disjoint_sets.h"

namespace areagraph {
namespace {

using cgal::Kernel;
using AlphaVertexBase =
    CGAL::Alpha_shape_vertex_base_2<Kernel,
                                    CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>>;
using AlphaFaceBase = CGAL::Alpha_shape_face_base_2<Kernel>;
using AlphaTds = CGAL::Triangulation_data_structure_2<AlphaVertexBase, AlphaFaceBase>;
using AlphaDelaunay = CGAL::Delaunay_triangulation_2<Kernel, AlphaTds>;
using AlphaShape = CGAL::Alpha_shape_2<AlphaDelaunay>;

// Points on one line (or a single point): Alpha_shape_2 only handles full
// dimension, so join consecutive points closer than the disk's diameter.
void CollinearComplex(const AlphaDelaunay& dt, double alpha_radius, DisjointSets& sets,
                      AlphaComplex& complex) {
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    const auto a = e->first->vertex(AlphaDelaunay::cw(e->second));
    const auto b = e->first->vertex(AlphaDelaunay::ccw(e->second));
    if (CGAL::squared_distance(a->point(), b->point()) <= 4 * alpha_radius * alpha_radius) {
      sets.Union(a->info(), b->info());
      complex.boundary_edges.push_back({a->info(), b->info(), true});
    }
  }
}

}  // namespace

AlphaComplex ComputeAlphaComplex(const std::vector<Eigen::Vector2d>& points, double alpha_radius) {
  AlphaComplex complex;
  DisjointSets sets(points.size());
  const auto indexed = cgal::IndexedPoints(points);
  AlphaDelaunay dt(indexed.begin(), indexed.end());
  if (dt.dimension() < 2) {
    CollinearComplex(dt, alpha_radius, sets, complex);
  } else {
    const AlphaShape shape(dt, alpha_radius * alpha_radius, AlphaShape::GENERAL);
    for (auto e = shape.finite_edges_begin(); e != shape.finite_edges_end(); ++e) {
      const auto type = shape.classify(*e);
      if (type == AlphaShape::EXTERIOR) continue;
      auto face = e->first;
      int i = e->second;
      sets.Union(face->vertex(AlphaShape::cw(i))->info(), face->vertex(AlphaShape::ccw(i))->info());
      if (type == AlphaShape::INTERIOR) continue;
      if (type == AlphaShape::REGULAR && shape.classify(face) != AlphaShape::INTERIOR) {
        const auto neighbor = face->neighbor(i);
        i = neighbor->index(face);
        face = neighbor;
      }
      // CGAL faces are counter-clockwise in the plane's own (y up) sense, so
      // the face lies on the CGAL-left of ccw(i) -> cw(i), which is the left
      // of cw(i) -> ccw(i) when y points down.
      complex.boundary_edges.push_back({face->vertex(AlphaShape::cw(i))->info(),
                                        face->vertex(AlphaShape::ccw(i))->info(),
                                        type == AlphaShape::SINGULAR});
    }
  }
  complex.component_of_point = sets.DenseLabels(&complex.component_count);
  return complex;
}

std::vector<double> ComponentPerimeters(const std::vector<Eigen::Vector2d>& points,
                                        const AlphaComplex& complex) {
  std::vector<double> perimeters(complex.component_count, 0.0);
  for (const AlphaShapeEdge& edge : complex.boundary_edges) {
    const double length = (points[edge.b] - points[edge.a]).norm();
    perimeters[complex.component_of_point[edge.a]] += edge.singular ? 2 * length : length;
  }
  return perimeters;
}

}  // namespace areagraph
