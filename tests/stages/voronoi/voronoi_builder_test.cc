#include "stages/voronoi/voronoi_builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <set>

#include "stages/geometry/disjoint_sets.h"
#include "tests/support/voronoi_messages.h"

namespace areagraph {
namespace {

Eigen::Vector2d P(const proto::Point2& p) { return {p.x(), p.y()}; }

// cross(u, v) = u.x * v.y - u.y * v.x; negative means v is on the left of u
// in pixel coordinates (y down).
double Cross(const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
  return u.x() * v.y() - u.y() * v.x();
}

Eigen::Vector2d Direction(const proto::VoronoiDiagram& d, const proto::VoronoiEdge& e) {
  if (e.target() < 0) return P(e.ray_direction());
  return P(d.vertices(e.target()).position()) - P(d.vertices(e.source()).position());
}

TEST(VoronoiBuilder, FourSitesInASquareMeetAtTheCentre) {
  const std::vector<Eigen::Vector2d> sites = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const proto::VoronoiDiagram d = VoronoiAsMessages(BuildVoronoiDiagram(sites));
  ASSERT_EQ(d.sites_size(), 4);
  ASSERT_EQ(d.vertices_size(), 1);  // two co-circular triangles, one vertex
  EXPECT_NEAR(d.vertices(0).position().x(), 5, 1e-9);
  EXPECT_NEAR(d.vertices(0).position().y(), 5, 1e-9);
  EXPECT_NEAR(d.vertices(0).clearance_px(), std::sqrt(50.0), 1e-9);
  ASSERT_EQ(d.edges_size(), 4);
  bool found_up = false;
  for (const proto::VoronoiEdge& e : d.edges()) {
    EXPECT_EQ(e.source(), 0);
    EXPECT_EQ(e.target(), -1);
    EXPECT_NEAR(P(e.ray_direction()).norm(), 1, 1e-12);
    EXPECT_NEAR(e.clearance_px(), 5, 1e-9);
    // The ray runs between its two sites, away from the centre.
    const Eigen::Vector2d mid = 0.5 * (sites[e.left_site()] + sites[e.right_site()]);
    EXPECT_NEAR((mid - Eigen::Vector2d(5, 5)).normalized().dot(P(e.ray_direction())), 1, 1e-9);
    if (e.ray_direction().y() < -0.5) {
      // Walking up the image (towards y = 0), (0,0) is on the left.
      found_up = true;
      EXPECT_EQ(e.left_site(), 0);
      EXPECT_EQ(e.right_site(), 1);
    }
  }
  EXPECT_TRUE(found_up);
}

TEST(VoronoiBuilder, CorridorCentreLineHasTheClearanceAndCorrectSides) {
  // Two walls 20 px apart: y = 0 and y = 20, x = 0..100.
  std::vector<Eigen::Vector2d> sites;
  for (int x = 0; x <= 100; ++x) {
    sites.emplace_back(x, 0);
    sites.emplace_back(x, 20);
  }
  const proto::VoronoiDiagram d = VoronoiAsMessages(BuildVoronoiDiagram(sites));
  int centre_edges = 0;
  double centre_length = 0;
  for (const proto::VoronoiEdge& e : d.edges()) {
    if (e.clearance_px() < 0.4 * 20) continue;
    ++centre_edges;
    const Eigen::Vector2d source = P(d.vertices(e.source()).position());
    EXPECT_NEAR(source.y(), 10, 1e-9);
    const Eigen::Vector2d direction = Direction(d, e);
    if (e.target() >= 0) {
      EXPECT_NEAR(d.vertices(e.target()).position().y(), 10, 1e-9);
      centre_length += direction.norm();
    }
    EXPECT_NEAR(e.clearance_px(), 10, 1e-9);
    // Walking towards +x, the wall at y = 0 is on the left (y down).
    const double wall_of_left = d.sites(e.left_site()).y();
    const double wall_of_right = d.sites(e.right_site()).y();
    if (direction.x() > 0) {
      EXPECT_EQ(wall_of_left, 0);
      EXPECT_EQ(wall_of_right, 20);
    } else {
      EXPECT_EQ(wall_of_left, 20);
      EXPECT_EQ(wall_of_right, 0);
    }
  }
  EXPECT_GE(centre_edges, 99);
  EXPECT_NEAR(centre_length, 99, 1e-6);  // vertices at x = 0.5 .. 99.5
  // Co-circular rectangles became single vertices: none coincide.
  std::set<std::pair<long, long>> seen;
  for (const proto::VoronoiVertex& v : d.vertices()) {
    EXPECT_TRUE(
        seen.insert({std::lround(v.position().x() * 1e6), std::lround(v.position().y() * 1e6)})
            .second);
  }
}

// Brute force checks of the diagram's definition on grid points (which are
// full of co-circular quadruples).
TEST(VoronoiBuilder, RandomGridSitesSatisfyTheDefinition) {
  std::mt19937 random(7);
  std::uniform_int_distribution<int> coordinate(0, 60);
  std::set<std::pair<int, int>> cells;
  while (cells.size() < 400) cells.insert({coordinate(random), coordinate(random)});
  std::vector<Eigen::Vector2d> sites;
  for (const auto& [col, row] : cells) sites.emplace_back(col + 0.5, row + 0.5);
  const proto::VoronoiDiagram d = VoronoiAsMessages(BuildVoronoiDiagram(sites));
  ASSERT_GT(d.vertices_size(), 100);

  auto nearest = [&](const Eigen::Vector2d& p) {
    double best = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector2d& s : sites) best = std::min(best, (s - p).norm());
    return best;
  };
  for (const proto::VoronoiVertex& v : d.vertices()) {
    EXPECT_NEAR(v.clearance_px(), nearest(P(v.position())), 1e-6);
  }
  DisjointSets connected(d.vertices_size());
  int components = d.vertices_size();
  for (const proto::VoronoiEdge& e : d.edges()) {
    ASSERT_GE(e.source(), 0);
    ASSERT_LT(e.source(), d.vertices_size());
    ASSERT_LT(e.target(), d.vertices_size());
    const Eigen::Vector2d source = P(d.vertices(e.source()).position());
    const Eigen::Vector2d left = sites[e.left_site()];
    const Eigen::Vector2d right = sites[e.right_site()];
    const Eigen::Vector2d direction = Direction(d, e);
    EXPECT_GT(direction.norm(), 1e-9);
    EXPECT_LT(Cross(direction, left - source), 0);
    EXPECT_GT(Cross(direction, right - source), 0);
    // Both sites are the nearest ones along the edge.
    const double clearance = d.vertices(e.source()).clearance_px();
    EXPECT_NEAR((left - source).norm(), clearance, 1e-6);
    EXPECT_NEAR((right - source).norm(), clearance, 1e-6);
    // Edge clearance: the minimum over the edge, sampled densely.
    const double length = e.target() < 0 ? 200.0 : 1.0;
    double sampled = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= 20000; ++k) {
      const Eigen::Vector2d p = source + direction * (length * k / 20000);
      sampled = std::min(sampled, (p - left).norm());
    }
    EXPECT_NEAR(e.clearance_px(), sampled, 1e-3);
    EXPECT_LE(e.clearance_px(), sampled + 1e-9);
    if (e.target() >= 0 && connected.Union(e.source(), e.target())) --components;
  }
  EXPECT_EQ(components, 1);
}

TEST(VoronoiBuilder, CollinearSitesGiveNoVertices) {
  const proto::VoronoiDiagram d =
      VoronoiAsMessages(BuildVoronoiDiagram({{0, 0}, {1, 1}, {2, 2}, {5, 5}}));
  EXPECT_EQ(d.sites_size(), 4);
  EXPECT_EQ(d.vertices_size(), 0);
  EXPECT_EQ(d.edges_size(), 0);
}

TEST(VoronoiBuilder, RaysCanBeLeftOut) {
  VoronoiBuildOptions options;
  options.keep_rays = false;
  const proto::VoronoiDiagram d =
      VoronoiAsMessages(BuildVoronoiDiagram({{0, 0}, {10, 0}, {10, 10}, {0, 10}, {5, 3}}, options));
  EXPECT_GT(d.edges_size(), 0);
  for (const proto::VoronoiEdge& e : d.edges()) EXPECT_GE(e.target(), 0);
}

}  // namespace
}  // namespace areagraph
