#include "stages/geometry/alpha_shape.h"

#include <cstdint>

#include "stages/geometry/disjoint_sets.h"
#include "stages/geometry/site_triangulation.h"
#include "stages/geometry/site_triangulation_cgal.h"

namespace areagraph {
namespace {

using SiteDelaunay = site_cgal::Delaunay;
using Face = SiteDelaunay::Face_handle;
using Point = site_cgal::Point;

// Twice a coordinate on the half-pixel grid, as an integer.
int64_t Twice(double value) { return static_cast<int64_t>(2 * value); }

// Whether t lies strictly inside the circle with diameter pq, (t - p) . (t - q)
// < 0: Epick's side_of_bounded_circle_2 == ON_BOUNDED_SIDE, in integers when
// the points are on the half-pixel grid (most pairs of grid points tie).
bool StrictlyInsideDiametralCircle(const Point& p, const Point& q, const Point& t,
                                   bool on_half_grid) {
  if (!on_half_grid) {
    return site_cgal::Kernel().side_of_bounded_circle_2_object()(p, q, t) == CGAL::ON_BOUNDED_SIDE;
  }
  const int64_t tx = Twice(t.x()), ty = Twice(t.y());
  return (tx - Twice(p.x())) * (tx - Twice(q.x())) + (ty - Twice(p.y())) * (ty - Twice(q.y())) < 0;
}

// Points on one line (or a single point): there are no faces, so join
// consecutive points closer than the disk's diameter.
void CollinearComplex(const SiteDelaunay& dt, double alpha_radius, DisjointSets& sets,
                      AlphaComplex& complex) {
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    const auto a = e->first->vertex(SiteDelaunay::cw(e->second));
    const auto b = e->first->vertex(SiteDelaunay::ccw(e->second));
    if (CGAL::squared_distance(a->point(), b->point()) <= 4 * alpha_radius * alpha_radius) {
      sets.Union(a->info(), b->info());
      complex.boundary_edges.push_back({a->info(), b->info(), true});
    }
  }
}

}  // namespace

// The complex for one alpha straight from the Delaunay triangulation, with
// the rules (and the very functors, so ties on the pixel grid come out the
// same) of CGAL's Alpha_shape_2 in GENERAL mode, which would first sort every
// face and edge by the alpha at which it appears:
// - a finite face is interior when its squared circumradius is <= alpha;
// - an edge of one or two interior faces is regular or interior;
// - an edge of no interior face is singular when its own smallest circle
//   (half its length) fits, i.e. squared half-length <= alpha, and is empty:
//   no opposite vertex lies strictly inside it ("not attached").
AlphaComplex ComputeAlphaComplex(const std::vector<Eigen::Vector2d>& points, double alpha_radius) {
  AlphaComplex complex;
  DisjointSets sets(points.size());
  // The site triangulation's traits: Epick with an integer in-circle test
  // when every point is on the half-pixel grid (ag-clean's cell centres), the
  // same exact signs, so the same triangulation.
  const SiteTriangulationPtr triangulation = TriangulateIndexedSites(points);
  SiteDelaunay& dt = triangulation->dt;
  if (dt.dimension() < 2) {
    CollinearComplex(dt, alpha_radius, sets, complex);
    complex.component_of_point = sets.DenseLabels(&complex.component_count);
    return complex;
  }

  const double alpha = alpha_radius * alpha_radius;
  const auto& traits = dt.geom_traits();
  const auto squared_radius = traits.compute_squared_radius_2_object();
  // Face info: the finite faces' numbers in iteration order, -1 for the
  // infinite ones.
  std::vector<char> interior;
  interior.reserve(dt.number_of_faces());
  for (auto f = dt.all_faces_begin(); f != dt.all_faces_end(); ++f) f->info().number = -1;
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    f->info().number = int(interior.size());
    const double face_alpha =
        squared_radius(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
    interior.push_back(face_alpha <= alpha);
  }
  auto is_interior = [&](const Face& face) {
    return face->info().number >= 0 && interior[face->info().number];
  };
  // An opposite vertex strictly inside the edge's diametral circle.
  auto attached = [&](const Face& face, int i) {
    return face->info().number >= 0 &&
           StrictlyInsideDiametralCircle(face->vertex(SiteDelaunay::cw(i))->point(),
                                         face->vertex(SiteDelaunay::ccw(i))->point(),
                                         face->vertex(i)->point(), traits.on_half_grid);
  };

  // Each edge once, from its finite face with the lower number. (CGAL's edge
  // iterator picks the side by comparing face addresses, which would make
  // the order of boundary_edges depend on the heap's history.)
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const Face neighbor = f->neighbor(k);
      if (neighbor->info().number >= 0 && neighbor->info().number < f->info().number) continue;
      const int interior_faces = is_interior(f) + is_interior(neighbor);
      const auto a = f->vertex(SiteDelaunay::cw(k));
      const auto b = f->vertex(SiteDelaunay::ccw(k));
      bool singular = false;
      if (interior_faces == 0) {
        if (squared_radius(b->point(), a->point()) > alpha) continue;
        if (attached(f, k) || attached(neighbor, neighbor->index(f))) continue;
        singular = true;
      }
      sets.Union(a->info(), b->info());
      if (interior_faces == 2) continue;
      Face face = f;
      int i = k;
      if (!singular && !is_interior(f)) {
        i = neighbor->index(f);
        face = neighbor;
      }
      // CGAL faces are counter-clockwise in the plane's own (y up) sense, so
      // the face lies on the CGAL-left of ccw(i) -> cw(i), which is the left
      // of cw(i) -> ccw(i) when y points down.
      complex.boundary_edges.push_back({face->vertex(SiteDelaunay::cw(i))->info(),
                                        face->vertex(SiteDelaunay::ccw(i))->info(), singular});
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
