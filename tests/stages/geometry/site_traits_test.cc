// The site triangulation with its half-grid in-circle test against Epick's
// own triangulation, face by face in the container's order (the order numbers
// the Voronoi vertices, so it must not move).
#include <gtest/gtest.h>

#include <random>

#include "stages/geometry/site_triangulation_cgal.h"

namespace areagraph {
namespace {

using site_cgal::Kernel;
using site_cgal::Point;

TEST(SiteTraitsTest, TheTriangulationIsTheKernelsFaceByFace) {
  using KernelDelaunay = CGAL::Delaunay_triangulation_2<Kernel, site_cgal::Tds>;
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
    site_cgal::Delaunay ours{site_cgal::Traits(true)};
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
