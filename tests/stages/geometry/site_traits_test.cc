// The site triangulation with its in-circle tests (integers on the half grid,
// a double filter then exact tests for mixed sites) against Epick's predicate
// and triangulation, face by face in the container's order (the order numbers
// the Voronoi vertices and cut's rooms' rings, so it must not move).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "stages/geometry/site_triangulation_cgal.h"

namespace areagraph {
namespace {

using site_cgal::Kernel;
using site_cgal::Point;

// The site triangulation of `sites` (with the traits' `on_half_grid`) has
// Epick's faces in Epick's container order, vertex by vertex.
void ExpectTheKernelsFaces(const std::vector<Point>& sites, bool on_half_grid, int round) {
  site_cgal::Delaunay ours{site_cgal::Traits(on_half_grid)};
  CGAL::Delaunay_triangulation_2<Kernel, site_cgal::Tds> theirs;
  ours.insert(sites.begin(), sites.end());
  theirs.insert(sites.begin(), sites.end());
  ASSERT_EQ(ours.number_of_faces(), theirs.number_of_faces());
  auto face = theirs.finite_faces_begin();
  for (const auto ours_face : ours.finite_face_handles()) {
    for (int i = 0; i < 3; ++i) {
      ASSERT_EQ(ours_face->vertex(i)->point(), face->vertex(i)->point()) << "round " << round;
    }
    ++face;
  }
}

TEST(SiteTraitsTest, TheTriangulationIsTheKernelsFaceByFace) {
  std::mt19937 random(15);
  std::uniform_int_distribution<int> cell(0, 70), kind(0, 3);
  for (int round = 0; round < 10; ++round) {
    // Cell centres and corners near one origin: many co-circular fours.
    std::vector<Point> sites;
    const double origin = 100.0 * round;
    for (int i = 0; i < 3000; ++i) {
      const double shift = kind(random) == 0 ? 0.0 : 0.5;
      sites.emplace_back(origin + cell(random) + shift, origin + cell(random) + shift);
    }
    ExpectTheKernelsFaces(sites, true, round);
  }
}

// Without the whole triangulation on the half grid (cut's sites: cell
// centres and the off-grid sites that close doors), each call checks its own
// four points: the sign is still Epick's, whichever way it is found.
TEST(SiteTraitsTest, MixedSitesGiveTheKernelsSigns) {
  std::mt19937 random(16);
  std::uniform_int_distribution<int> cell(-6, 6), kind(0, 7);
  std::uniform_real_distribution<double> fraction(0.0, 1.0);
  const site_cgal::Traits::Side_of_oriented_circle_2 ours =
      site_cgal::Traits(false).side_of_oriented_circle_2_object();
  const auto theirs = Kernel().side_of_oriented_circle_2_object();
  const double limit = site_cgal::Traits::Side_of_oriented_circle_2::kMixedLimit;
  int co_circular = 0, off_grid = 0;
  for (const double origin :
       {0.0, 4000.0, limit - 6, limit - 3, limit + 0.5, -limit - 0.5, -20000.0}) {
    for (int i = 0; i < 100000; ++i) {
      Point points[4];
      bool on_grid = true;
      for (Point& point : points) {
        double x = origin + cell(random) + 0.5 * (kind(random) % 2);
        double y = origin + cell(random) + 0.5 * (kind(random) % 2);
        if (kind(random) == 0) {  // a door's line site, or one near the grid
          x += kind(random) == 0 ? 1e-9 : fraction(random);
          on_grid = false;
        }
        point = Point(x, y);
      }
      off_grid += !on_grid;
      const CGAL::Oriented_side expected = theirs(points[0], points[1], points[2], points[3]);
      co_circular += expected == CGAL::ON_ORIENTED_BOUNDARY;
      ASSERT_EQ(ours(points[0], points[1], points[2], points[3]), expected)
          << "origin " << origin << " quadruple " << i;
    }
  }
  EXPECT_GT(co_circular, 3000) << "the degenerate cases were not exercised";
  EXPECT_GT(off_grid, 100000);
}

TEST(SiteTraitsTest, MixedSitesTriangulateAsTheKernelFaceByFace) {
  std::mt19937 random(17);
  std::uniform_int_distribution<int> cell(0, 70), kind(0, 50);
  std::uniform_real_distribution<double> fraction(0.0, 1.0);
  for (int round = 0; round < 6; ++round) {
    std::vector<Point> sites;
    const double origin = 1500.0 * round;
    for (int i = 0; i < 3000; ++i) {
      const bool line_site = kind(random) == 0;
      sites.emplace_back(origin + cell(random) + (line_site ? fraction(random) : 0.5),
                         origin + cell(random) + 0.5);
    }
    ExpectTheKernelsFaces(sites, false, round);
  }
}

// Off the grid, four points on one circle (rounded to double) are so nearly
// co-circular that the rounding of the double determinant decides its sign:
// the filter must leave them to the exact test.
TEST(SiteTraitsTest, NearlyCoCircularPointsOffTheGridGiveTheKernelsSigns) {
  std::mt19937 random(18);
  std::uniform_real_distribution<double> angle(0.0, 2 * M_PI), unit(0.0, 1.0);
  const site_cgal::Traits::Side_of_oriented_circle_2 ours =
      site_cgal::Traits(false).side_of_oriented_circle_2_object();
  const auto theirs = Kernel().side_of_oriented_circle_2_object();
  int boundary = 0;
  for (int i = 0; i < 200000; ++i) {
    const double cx = 8000 * unit(random) - 4000, cy = 8000 * unit(random) - 4000;
    const double radius = 0.5 + 40 * unit(random);
    Point points[4];
    for (Point& point : points) {
      const double at = angle(random);
      point = Point(cx + radius * std::cos(at), cy + radius * std::sin(at));
    }
    const CGAL::Oriented_side expected = theirs(points[0], points[1], points[2], points[3]);
    boundary += expected == CGAL::ON_ORIENTED_BOUNDARY;
    ASSERT_EQ(ours(points[0], points[1], points[2], points[3]), expected) << "quadruple " << i;
  }
  EXPECT_LT(boundary, 1000) << "the points were meant to be off the circle by rounding only";
}

}  // namespace
}  // namespace areagraph
