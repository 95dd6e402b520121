#include "stages/voronoi/voronoi_builder.h"

#include <cmath>

#include "stages/geometry/cgal_types.h"
#include "stages/geometry/disjoint_sets.h"

namespace areagraph {
namespace {

using cgal::SiteDelaunay;
using Face = SiteDelaunay::Face_handle;

// Numbers the finite faces (face info, in iteration order; infinite faces
// get -1).
int NumberFaces(SiteDelaunay& dt) {
  int count = 0;
  for (auto f = dt.all_faces_begin(); f != dt.all_faces_end(); ++f) f->info() = -1;
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) f->info() = count++;
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
      if (n->info() < f->info()) continue;  // infinite, or seen from the other side
      const auto& opposite = n->vertex(n->index(f))->point();
      if (side_of_circle(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point(),
                         opposite) == CGAL::ON_ORIENTED_BOUNDARY) {
        sets.Union(f->info(), n->info());
      }
    }
  }
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

// One Voronoi edge before it becomes a message.
struct PlainEdge {
  int source;
  int target;
  int left_site;
  int right_site;
  double clearance_px;
  // Index into PlainDiagram::ray_directions, or -1 for a segment.
  int ray;
};

// The diagram as plain arrays: the triangulation is gone before the messages
// are made, so that on a big map (a million sites) the two never take memory
// at the same time.
struct PlainDiagram {
  bool has_faces = false;
  std::vector<Eigen::Vector2d> positions;
  std::vector<double> clearances;
  std::vector<PlainEdge> edges;
  std::vector<Eigen::Vector2d> ray_directions;
};

// The dual of the sites' Delaunay triangulation (see BuildVoronoiDiagram).
PlainDiagram DualOfTriangulation(const std::vector<Eigen::Vector2d>& sites,
                                 const VoronoiBuildOptions& options) {
  PlainDiagram plain;
  const auto indexed = cgal::IndexedPoints(sites);
  SiteDelaunay dt(indexed.begin(), indexed.end());
  if (dt.dimension() < 2) return plain;
  plain.has_faces = true;

  const int face_count = NumberFaces(dt);
  int vertex_count = 0;
  const std::vector<int> vertex_of_face =
      MergeCocircularFaces(dt, face_count).DenseLabels(&vertex_count);

  // One Voronoi vertex per circle, placed at the first face's circumcentre.
  std::vector<Eigen::Vector2d>& positions = plain.positions;
  std::vector<double>& clearances = plain.clearances;
  positions.resize(vertex_count);
  clearances.assign(vertex_count, -1.0);
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    const int vertex = vertex_of_face[f->info()];
    if (clearances[vertex] >= 0) continue;
    const auto centre = dt.circumcenter(f);
    positions[vertex] = cgal::ToEigen(centre);
    clearances[vertex] = std::sqrt(CGAL::squared_distance(centre, f->vertex(0)->point()));
  }

  // Each Delaunay edge once, from its finite face with the lower number
  // towards the other face. (CGAL's edge iterator picks the side by comparing
  // face addresses, which would make the output depend on the heap's history.)
  plain.edges.reserve(dt.number_of_vertices() + face_count);
  for (auto face = dt.finite_faces_begin(); face != dt.finite_faces_end(); ++face) {
    for (int i = 0; i < 3; ++i) {
      const Face other = face->neighbor(i);
      const bool is_ray = other->info() < 0;
      if (!is_ray && other->info() < face->info()) continue;
      if (is_ray && !options.keep_rays) continue;
      const int source = vertex_of_face[face->info()];
      const int target = is_ray ? -1 : vertex_of_face[other->info()];
      if (source == target) continue;

      // `face` is counter-clockwise in CGAL's (y up) sense, so moving out of
      // it across the edge ccw(i) -> cw(i), vertex ccw(i) is on the
      // CGAL-right, which is the left when y points down.
      const auto left = face->vertex(SiteDelaunay::ccw(i));
      const auto right = face->vertex(SiteDelaunay::cw(i));
      const Eigen::Vector2d left_site = cgal::ToEigen(left->point());
      const Eigen::Vector2d right_site = cgal::ToEigen(right->point());

      PlainEdge edge{source, target, left->info(), right->info(), 0, -1};
      if (is_ray) {
        // Perpendicular to the hull edge, pointing away from the face: the
        // face is on the CGAL-left of left_site -> right_site, so take its
        // right normal.
        const Eigen::Vector2d along = right_site - left_site;
        const Eigen::Vector2d direction = Eigen::Vector2d(along.y(), -along.x()).normalized();
        edge.ray = static_cast<int>(plain.ray_directions.size());
        plain.ray_directions.push_back(direction);
        edge.clearance_px =
            EdgeClearance(positions[source], direction, INFINITY, clearances[source],
                          clearances[source], left_site, right_site);
      } else {
        edge.clearance_px =
            EdgeClearance(positions[source], positions[target] - positions[source], 1.0,
                          clearances[source], clearances[target], left_site, right_site);
      }
      plain.edges.push_back(edge);
    }
  }
  return plain;
}

}  // namespace

proto::VoronoiDiagram BuildVoronoiDiagram(const std::vector<Eigen::Vector2d>& sites,
                                          const VoronoiBuildOptions& options) {
  PlainDiagram plain = DualOfTriangulation(sites, options);
  proto::VoronoiDiagram diagram;
  diagram.mutable_sites()->Reserve(int(sites.size()));
  for (const Eigen::Vector2d& site : sites) SetPoint(site, diagram.add_sites());
  if (!plain.has_faces) return diagram;

  diagram.mutable_vertices()->Reserve(int(plain.positions.size()));
  for (size_t v = 0; v < plain.positions.size(); ++v) {
    proto::VoronoiVertex* vertex = diagram.add_vertices();
    SetPoint(plain.positions[v], vertex->mutable_position());
    vertex->set_clearance_px(plain.clearances[v]);
  }
  std::vector<Eigen::Vector2d>().swap(plain.positions);
  std::vector<double>().swap(plain.clearances);

  diagram.mutable_edges()->Reserve(int(plain.edges.size()));
  for (const PlainEdge& plain_edge : plain.edges) {
    proto::VoronoiEdge* edge = diagram.add_edges();
    edge->set_source(plain_edge.source);
    edge->set_target(plain_edge.target);
    edge->set_left_site(plain_edge.left_site);
    edge->set_right_site(plain_edge.right_site);
    if (plain_edge.ray >= 0) {
      SetPoint(plain.ray_directions[plain_edge.ray], edge->mutable_ray_direction());
    }
    edge->set_clearance_px(plain_edge.clearance_px);
  }
  return diagram;
}

}  // namespace areagraph
