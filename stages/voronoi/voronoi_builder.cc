#include "stages/voronoi/voronoi_builder.h"

#include <cmath>

#include "stages/geometry/cgal_types.h"
#include "stages/geometry/disjoint_sets.h"

namespace areagraph {
namespace {

using cgal::SiteDelaunay;
using Face = SiteDelaunay::Face_handle;

// Numbers the finite faces (face info) and merges neighbours whose
// circumcircles are the same circle: the fourth point lying exactly on the
// circle is an exact predicate, so no tolerance is involved.
DisjointSets MergeCocircularFaces(SiteDelaunay& dt, int* face_count) {
  int count = 0;
  for (auto f = dt.all_faces_begin(); f != dt.all_faces_end(); ++f) f->info() = -1;
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) f->info() = count++;
  DisjointSets sets(count);
  const auto side_of_circle = dt.geom_traits().side_of_oriented_circle_2_object();
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    const Face f = e->first;
    const Face n = f->neighbor(e->second);
    if (dt.is_infinite(f) || dt.is_infinite(n)) continue;
    const auto& opposite = n->vertex(n->index(f))->point();
    if (side_of_circle(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point(),
                       opposite) == CGAL::ON_ORIENTED_BOUNDARY) {
      sets.Union(f->info(), n->info());
    }
  }
  *face_count = count;
  return sets;
}

void SetPoint(const Eigen::Vector2d& p, proto::Point2* out) {
  out->set_x(p.x());
  out->set_y(p.y());
}

// Smallest distance from the part of the bisector between `from` and `to` to
// the two sites: half their distance when their midpoint lies on that part,
// else the nearer end's clearance. The part is from + t * direction for t in
// [0, t_max]: t_max is 1 for segments and infinity for rays.
double EdgeClearance(const Eigen::Vector2d& from, const Eigen::Vector2d& direction, double t_max,
                     double from_clearance, double to_clearance, const Eigen::Vector2d& site_a,
                     const Eigen::Vector2d& site_b) {
  const Eigen::Vector2d midpoint = 0.5 * (site_a + site_b);
  const double length2 = direction.squaredNorm();
  const double t = length2 > 0 ? (midpoint - from).dot(direction) / length2 : 0.0;
  if (t >= 0 && t <= t_max) return 0.5 * (site_b - site_a).norm();
  return std::min(from_clearance, to_clearance);
}

}  // namespace

proto::VoronoiDiagram BuildVoronoiDiagram(const std::vector<Eigen::Vector2d>& sites,
                                          const VoronoiBuildOptions& options) {
  proto::VoronoiDiagram diagram;
  diagram.mutable_sites()->Reserve(int(sites.size()));
  for (const Eigen::Vector2d& site : sites) SetPoint(site, diagram.add_sites());

  const auto indexed = cgal::IndexedPoints(sites);
  SiteDelaunay dt(indexed.begin(), indexed.end());
  if (dt.dimension() < 2) return diagram;

  int face_count = 0;
  DisjointSets cocircular = MergeCocircularFaces(dt, &face_count);
  int vertex_count = 0;
  const std::vector<int> vertex_of_face = cocircular.DenseLabels(&vertex_count);

  // One Voronoi vertex per circle, placed at the first face's circumcentre.
  std::vector<Eigen::Vector2d> positions(vertex_count);
  std::vector<double> clearances(vertex_count, -1.0);
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    const int vertex = vertex_of_face[f->info()];
    if (clearances[vertex] >= 0) continue;
    const auto centre = dt.circumcenter(f);
    positions[vertex] = cgal::ToEigen(centre);
    clearances[vertex] = std::sqrt(CGAL::squared_distance(centre, f->vertex(0)->point()));
  }
  diagram.mutable_vertices()->Reserve(vertex_count);
  for (int v = 0; v < vertex_count; ++v) {
    proto::VoronoiVertex* vertex = diagram.add_vertices();
    SetPoint(positions[v], vertex->mutable_position());
    vertex->set_clearance_px(clearances[v]);
  }

  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    // Walk from a finite face towards its neighbour across the Delaunay edge.
    Face face = e->first;
    int i = e->second;
    if (dt.is_infinite(face)) {
      const Face neighbor = face->neighbor(i);
      i = neighbor->index(face);
      face = neighbor;
    }
    const Face other = face->neighbor(i);
    const bool is_ray = dt.is_infinite(other);
    if (is_ray && !options.keep_rays) continue;
    const int source = vertex_of_face[face->info()];
    const int target = is_ray ? -1 : vertex_of_face[other->info()];
    if (source == target) continue;

    // `face` is counter-clockwise in CGAL's (y up) sense, so moving out of it
    // across the edge ccw(i) -> cw(i), vertex ccw(i) is on the CGAL-right,
    // which is the left when y points down.
    const auto left = face->vertex(SiteDelaunay::ccw(i));
    const auto right = face->vertex(SiteDelaunay::cw(i));
    const Eigen::Vector2d left_site = cgal::ToEigen(left->point());
    const Eigen::Vector2d right_site = cgal::ToEigen(right->point());

    proto::VoronoiEdge* edge = diagram.add_edges();
    edge->set_source(source);
    edge->set_target(target);
    edge->set_left_site(left->info());
    edge->set_right_site(right->info());
    if (is_ray) {
      // Perpendicular to the hull edge, pointing away from the face: the face
      // is on the CGAL-left of left_site -> right_site, so take its right normal.
      const Eigen::Vector2d along = right_site - left_site;
      const Eigen::Vector2d direction = Eigen::Vector2d(along.y(), -along.x()).normalized();
      SetPoint(direction, edge->mutable_ray_direction());
      edge->set_clearance_px(EdgeClearance(positions[source], direction, INFINITY,
                                           clearances[source], clearances[source], left_site,
                                           right_site));
    } else {
      edge->set_clearance_px(EdgeClearance(positions[source], positions[target] - positions[source],
                                           1.0, clearances[source], clearances[target], left_site,
                                           right_site));
    }
  }
  return diagram;
}

}  // namespace areagraph
