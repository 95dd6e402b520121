// BuildVoronoiDiagram works on flat face arrays (one pass over CGAL's faces,
// then arrays). These tests hold it to the plain way of taking the dual,
// written here by following the faces' pointers in every pass: the same
// bytes, and the same Voronoi vertex written on every face (prune's walks
// start there).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "stages/geometry/disjoint_sets.h"
#include "stages/geometry/site_triangulation_cgal.h"
#include "stages/voronoi/voronoi_builder.h"

namespace areagraph {
namespace {

using Delaunay = site_cgal::Delaunay;
using Face = Delaunay::Face_handle;

double ReferenceClearance(const Eigen::Vector2d& from, const Eigen::Vector2d& direction,
                          double t_max, double from_clearance, double to_clearance,
                          const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d midpoint = 0.5 * (a + b);
  const double length2 = direction.squaredNorm();
  const double t = length2 > 0 ? (midpoint - from).dot(direction) / length2 : 0.0;
  if (t >= 0 && t <= t_max) return 0.5 * (b - a).norm();
  return std::min(from_clearance, to_clearance);
}

Eigen::Vector2d Vec(const site_cgal::Point& p) { return {p.x(), p.y()}; }

// The dual as the builder took it before it used arrays: faces numbered in
// CGAL's order, co-circular neighbours merged (tested from the lower
// face), vertices at their first face's circumcentre, edges from the lower
// face. Leaves each face's Voronoi vertex in its number.
proto::VoronoiDiagram ReferenceDual(const std::vector<Eigen::Vector2d>& sites, bool keep_rays,
                                    SiteTriangulationPtr* kept) {
  proto::VoronoiDiagram d;
  for (const Eigen::Vector2d& site : sites) {
    d.add_site_x(site.x());
    d.add_site_y(site.y());
  }
  SiteTriangulationPtr triangulation = TriangulateIndexedSites(sites);
  Delaunay& dt = triangulation->dt;
  if (dt.dimension() == 2) {
    int faces = 0;
    for (auto f = dt.all_faces_begin(); f != dt.all_faces_end(); ++f) f->info().number = -1;
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
      f->info().number = faces++;
    }
    DisjointSets sets(faces);
    const auto side = dt.geom_traits().side_of_oriented_circle_2_object();
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
      for (int i = 0; i < 3; ++i) {
        const Face n = f->neighbor(i);
        if (n->info().number < f->info().number) continue;
        if (side(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point(),
                 n->vertex(n->index(f))->point()) == CGAL::ON_ORIENTED_BOUNDARY) {
          sets.Union(f->info().number, n->info().number);
        }
      }
    }
    int vertices = 0;
    const std::vector<int> vertex_of = sets.DenseLabels(&vertices);
    std::vector<Eigen::Vector2d> position(vertices);
    std::vector<double> clearance(vertices, -1);
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
      const int v = vertex_of[f->info().number];
      if (clearance[v] >= 0) continue;
      const auto centre = dt.circumcenter(f);
      position[v] = Vec(centre);
      clearance[v] = std::sqrt(CGAL::squared_distance(centre, f->vertex(0)->point()));
    }
    for (int v = 0; v < vertices; ++v) {
      d.add_vertex_x(position[v].x());
      d.add_vertex_y(position[v].y());
      d.add_vertex_clearance_px(clearance[v]);
    }
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
      for (int i = 0; i < 3; ++i) {
        const Face other = f->neighbor(i);
        const bool ray = other->info().number < 0;
        if (!ray && other->info().number < f->info().number) continue;
        if (ray && !keep_rays) continue;
        const int source = vertex_of[f->info().number];
        const int target = ray ? -1 : vertex_of[other->info().number];
        if (source == target) continue;
        const auto left = f->vertex(Delaunay::ccw(i));
        const auto right = f->vertex(Delaunay::cw(i));
        const Eigen::Vector2d a = Vec(left->point()), b = Vec(right->point());
        double c;
        if (ray) {
          const Eigen::Vector2d along = b - a;
          const Eigen::Vector2d direction = Eigen::Vector2d(along.y(), -along.x()).normalized();
          d.add_ray_direction_x(direction.x());
          d.add_ray_direction_y(direction.y());
          c = ReferenceClearance(position[source], direction, INFINITY, clearance[source],
                                 clearance[source], a, b);
        } else {
          c = ReferenceClearance(position[source], position[target] - position[source], 1.0,
                                 clearance[source], clearance[target], a, b);
        }
        d.add_edge_source(source);
        d.add_edge_target(target);
        d.add_edge_left_site(left->info());
        d.add_edge_right_site(right->info());
        d.add_edge_clearance_px(c);
      }
    }
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
      f->info().number = vertex_of[f->info().number];
    }
  }
  *kept = std::move(triangulation);
  return d;
}

std::vector<int> FaceNumbers(const SiteTriangulation& triangulation) {
  std::vector<int> numbers;
  for (auto f = triangulation.dt.all_faces_begin(); f != triangulation.dt.all_faces_end(); ++f) {
    numbers.push_back(f->info().number);
  }
  return numbers;
}

// Builds both ways and compares; returns the diagram's vertex count.
int ExpectSameAsReference(const std::vector<Eigen::Vector2d>& sites, bool keep_rays) {
  SiteTriangulationPtr reference_faces, faces;
  const std::string reference =
      ReferenceDual(sites, keep_rays, &reference_faces).SerializeAsString();
  VoronoiBuildOptions options;
  options.keep_rays = keep_rays;
  const proto::VoronoiDiagram built = BuildVoronoiDiagram(sites, options, &faces);
  EXPECT_TRUE(built.SerializeAsString() == reference) << sites.size() << " sites";
  EXPECT_EQ(FaceNumbers(*faces), FaceNumbers(*reference_faces));
  return built.vertex_x_size();
}

// Cells of a span x span grid, at cell centres: most quadruples co-circular.
std::vector<Eigen::Vector2d> GridCells(std::mt19937* random, int count, int span) {
  std::set<std::pair<int, int>> cells;
  while (static_cast<int>(cells.size()) < count) {
    cells.insert({static_cast<int>((*random)() % span), static_cast<int>((*random)() % span)});
  }
  std::vector<Eigen::Vector2d> sites;
  for (const auto& [col, row] : cells) sites.emplace_back(col + 0.5, row + 0.5);
  std::shuffle(sites.begin(), sites.end(), *random);
  return sites;
}

TEST(VoronoiDual, SameAsFollowingTheFacesOnGrids) {
  std::mt19937 random(14);
  int vertices = 0;
  for (int round = 0; round < 40; ++round) {
    const int span = 5 + round * 3;
    const auto sites = GridCells(&random, span * span / (2 + round % 4), span);
    vertices += ExpectSameAsReference(sites, /*keep_rays=*/round % 3 != 0);
  }
  EXPECT_GT(vertices, 10000);
}

TEST(VoronoiDual, SameAsFollowingTheFacesOffTheGrid) {
  std::mt19937 random(15);
  std::uniform_real_distribution<double> coordinate(-50, 50);
  for (int round = 0; round < 20; ++round) {
    std::vector<Eigen::Vector2d> sites;
    for (int i = 0; i < 50 + 100 * round; ++i)
      sites.emplace_back(coordinate(random), coordinate(random));
    // A regular octagon and its centre: eight co-circular faces' worth.
    for (int k = 0; k < 8; ++k) {
      sites.emplace_back(60 + 5 * std::cos(k * M_PI / 4), 60 + 5 * std::sin(k * M_PI / 4));
    }
    ExpectSameAsReference(sites, /*keep_rays=*/round % 2 == 0);
  }
}

TEST(VoronoiDual, SameAsFollowingTheFacesOnSmallSets) {
  ExpectSameAsReference({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, true);
  ExpectSameAsReference({{0, 0}, {1, 0}, {2, 0}, {1, 1}}, true);
  ExpectSameAsReference({{0.5, 0.5}, {1.5, 0.5}, {2.5, 0.5}}, true);  // collinear: no faces
  ExpectSameAsReference({{0.5, 0.5}, {1.5, 0.5}, {0.5, 1.5}}, false);
}

}  // namespace
}  // namespace areagraph
