// The site triangulation's in-circle test (exact in integers on the cell
// grid) against the kernel's, and its triangulation against the kernel's one,
// face by face in the container's order.
#include <gtest/gtest.h>

#include <random>

#include "stages/geometry/site_triangulation_cgal.h"

namespace areagraph {
namespace {

using site_cgal::Kernel;
using site_cgal::Point;

// Cell centres near `origin` (many co-circular fours), now and then a point
// off the grid or one just past the grid's bound.
Point RandomSite(std::mt19937& random, double origin, int spread) {
  std::uniform_int_distribution<int> cell(0, spread), kind(0, 19);
  const double x = origin + cell(random) + 0.5, y = origin + cell(random) + 0.5;
  switch (kind(random)) {
    case 0:
      return Point(x + 0.25, y);
    case 1:
      return Point(x, y - 1e-9);
    case 2:
      return Point(x + 8192, y);
    case 3:
      return Point(-x, y);
    default:
      return Point(x, y);
  }
}

TEST(SiteTraitsTest, InCircleEqualsTheKernels) {
  const site_cgal::Traits traits;
  const auto grid = traits.side_of_oriented_circle_2_object();
  const auto kernel = Kernel().side_of_oriented_circle_2_object();
  std::mt19937 random(14);
  int on_circle = 0;
  for (const double origin : {0.0, 4000.0, 8180.0, -8191.0}) {
    for (int round = 0; round < 200000; ++round) {
      Point p[4];
      for (Point& point : p) point = RandomSite(random, origin, round % 2 == 0 ? 6 : 40);
      const CGAL::Oriented_side expected = kernel(p[0], p[1], p[2], p[3]);
      ASSERT_EQ(grid(p[0], p[1], p[2], p[3]), expected)
          << p[0] << " | " << p[1] << " | " << p[2] << " | " << p[3];
      on_circle += expected == CGAL::ON_ORIENTED_BOUNDARY;
    }
  }
  EXPECT_GT(on_circle, 10000);
}

TEST(SiteTraitsTest, TheTriangulationIsTheKernelsFaceByFace) {
  using KernelDelaunay = CGAL::Delaunay_triangulation_2<Kernel, site_cgal::Tds>;
  std::mt19937 random(15);
  for (int round = 0; round < 10; ++round) {
    std::vector<Point> sites;
    for (int i = 0; i < 3000; ++i) sites.push_back(RandomSite(random, 100.0 * round, 70));
    site_cgal::Delaunay ours;
    KernelDelaunay theirs;
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
}

}  // namespace
}  // namespace areagraph
