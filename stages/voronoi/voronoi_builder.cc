#include "stages/voronoi/voronoi_builder.h"

#include <cmath>

#include "stages/geometry/cgal_types.h"
#include "stages/geometry/disjoint_sets.h"
#include "stages/geometry/site_triangulation_cgal.h"

namespace areagraph {
namespace {

using SiteDelaunay = site_cgal::Delaunay;
using Face = SiteDelaunay::Face_handle;

// Numbers the finite faces (face info's number, in iteration order;
// infinite faces get -1).
int NumberFaces(SiteDelaunay& dt) {
  int count = 0;
  for (auto f = dt.all_faces_begin(); f != dt.all_faces_end(); ++f) f->info().number = -1;
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    f->info().number = count++;
  }
  return count;
}

// Merges neighbouring faces whose circumcircles are the same circle: the
// fourth point lying exactly on the circle is an exact predicate, so no
// tolerance is involved.
DisjointSets MergeCocircularFaces(const SiteDelaunay& dt, int face_count) {
  DisjointSets sets(face_count);
  const auto side_of_circle = dt.geom_traits().side_of_oriented_circle_2_object();
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    for (int i = 0; i < 3; ++i) {
      const Face n = f->neighbor(i);
      if (n->info().number < f->info().number) continue;  // infinite, or seen from the other side
      const auto& opposite = n->vertex(n->index(f))->point();
      if (side_of_circle(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point(),
                         opposite) == CGAL::ON_ORIENTED_BOUNDARY) {
        sets.Union(f->info().number, n->info().number);
      }
    }
  }
  return sets;
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

// Fills the diagram's vertex and edge arrays with the dual of the sites'
// Delaunay triangulation `dt` (see BuildVoronoiDiagram). The arrays take about
// the memory of the plain structs the messages of format 1 were made from.
void AddDualOfTriangulation(SiteDelaunay& dt, const VoronoiBuildOptions& options,
                            proto::VoronoiDiagram* diagram) {
  if (dt.dimension() < 2) return;

  const int face_count = NumberFaces(dt);
  int vertex_count = 0;
  const std::vector<int> vertex_of_face =
      MergeCocircularFaces(dt, face_count).DenseLabels(&vertex_count);

  // One Voronoi vertex per circle, placed at the first face's circumcentre.
  auto& xs = *diagram->mutable_vertex_x();
  auto& ys = *diagram->mutable_vertex_y();
  auto& clearances = *diagram->mutable_vertex_clearance_px();
  xs.Resize(vertex_count, 0.0);
  ys.Resize(vertex_count, 0.0);
  clearances.Resize(vertex_count, -1.0);
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    const int vertex = vertex_of_face[f->info().number];
    if (clearances[vertex] >= 0) continue;
    const auto centre = dt.circumcenter(f);
    xs[vertex] = centre.x();
    ys[vertex] = centre.y();
    clearances[vertex] = std::sqrt(CGAL::squared_distance(centre, f->vertex(0)->point()));
  }
  auto position = [&](int vertex) { return Eigen::Vector2d(xs[vertex], ys[vertex]); };

  // Each Delaunay edge once, from its finite face with the lower number
  // towards the other face. (CGAL's edge iterator picks the side by comparing
  // face addresses, which would make the output depend on the heap's history.)
  // Sized once: on a large map, doubling would hold two copies for a moment.
  const int most_edges = static_cast<int>(dt.number_of_vertices()) + face_count;
  for (auto* field : {diagram->mutable_edge_source(), diagram->mutable_edge_target(),
                      diagram->mutable_edge_left_site(), diagram->mutable_edge_right_site()}) {
    field->Reserve(most_edges);
  }
  diagram->mutable_edge_clearance_px()->Reserve(most_edges);
  for (auto face = dt.finite_faces_begin(); face != dt.finite_faces_end(); ++face) {
    for (int i = 0; i < 3; ++i) {
      const Face other = face->neighbor(i);
      const int number = face->info().number;
      const int other_number = other->info().number;
      const bool is_ray = other_number < 0;
      if (!is_ray && other_number < number) continue;
      if (is_ray && !options.keep_rays) continue;
      const int source = vertex_of_face[number];
      const int target = is_ray ? -1 : vertex_of_face[other_number];
      if (source == target) continue;

      // `face` is counter-clockwise in CGAL's (y up) sense, so moving out of
      // it across the edge ccw(i) -> cw(i), vertex ccw(i) is on the
      // CGAL-right, which is the left when y points down.
      const auto left = face->vertex(SiteDelaunay::ccw(i));
      const auto right = face->vertex(SiteDelaunay::cw(i));
      const Eigen::Vector2d left_site = cgal::ToEigen(left->point());
      const Eigen::Vector2d right_site = cgal::ToEigen(right->point());

      double clearance;
      if (is_ray) {
        // Perpendicular to the hull edge, pointing away from the face: the
        // face is on the CGAL-left of left_site -> right_site, so take its
        // right normal.
        const Eigen::Vector2d along = right_site - left_site;
        const Eigen::Vector2d direction = Eigen::Vector2d(along.y(), -along.x()).normalized();
        diagram->add_ray_direction_x(direction.x());
        diagram->add_ray_direction_y(direction.y());
        clearance = EdgeClearance(position(source), direction, INFINITY, clearances[source],
                                  clearances[source], left_site, right_site);
      } else {
        clearance = EdgeClearance(position(source), position(target) - position(source), 1.0,
                                  clearances[source], clearances[target], left_site, right_site);
      }
      diagram->add_edge_source(source);
      diagram->add_edge_target(target);
      diagram->add_edge_left_site(left->info());
      diagram->add_edge_right_site(right->info());
      diagram->add_edge_clearance_px(clearance);
    }
  }
  // Each face now names its Voronoi vertex (prune's locate walks start there).
  for (auto face = dt.finite_faces_begin(); face != dt.finite_faces_end(); ++face) {
    face->info().number = vertex_of_face[face->info().number];
  }
}

}  // namespace

proto::VoronoiDiagram BuildVoronoiDiagram(const std::vector<Eigen::Vector2d>& sites,
                                          const VoronoiBuildOptions& options) {
  return BuildVoronoiDiagram(sites, options, nullptr);
}

proto::VoronoiDiagram BuildVoronoiDiagram(const std::vector<Eigen::Vector2d>& sites,
                                          const VoronoiBuildOptions& options,
                                          SiteTriangulationPtr* triangulation_out) {
  proto::VoronoiDiagram diagram;
  diagram.mutable_site_x()->Reserve(int(sites.size()));
  diagram.mutable_site_y()->Reserve(int(sites.size()));
  for (const Eigen::Vector2d& site : sites) {
    diagram.add_site_x(site.x());
    diagram.add_site_y(site.y());
  }
  SiteTriangulationPtr triangulation = TriangulateIndexedSites(sites);
  AddDualOfTriangulation(triangulation->dt, options, &diagram);
  if (triangulation_out != nullptr) *triangulation_out = std::move(triangulation);
  return diagram;
}

}  // namespace areagraph
