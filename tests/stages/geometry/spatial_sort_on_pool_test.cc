// SpatialSortThenInsert (stages/geometry/spatial_sort_on_pool.h) puts points
// in CGAL::spatial_sort's order on one thread and on two and hands them to
// the insertion in that order, in consecutive pieces; the site
// triangulations built with it are CGAL's range insert face for face.
#include "stages/geometry/spatial_sort_on_pool.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "stages/geometry/site_triangulation.h"
#include "stages/geometry/site_triangulation_cgal.h"
#include "tests/support/thread_count.h"

namespace areagraph {
namespace {

using testing::ThreadCount;

// Cell centres of a random map (many equal x and y: the median splits meet
// ties) and a few points off the grid, as cut's sites are.
std::vector<Eigen::Vector2d> MapLikeSites(int count, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> cell(0, 400);
  std::uniform_real_distribution<double> off(0, 400);
  std::vector<Eigen::Vector2d> sites;
  for (int i = 0; i < count; ++i) {
    if (i % 50 == 0) {
      sites.emplace_back(off(random), off(random));
    } else {
      sites.emplace_back(cell(random) + 0.5, cell(random) + 0.5);
    }
  }
  return sites;
}

std::vector<site_cgal::Point> KernelPoints(const std::vector<Eigen::Vector2d>& sites) {
  std::vector<site_cgal::Point> points;
  for (const Eigen::Vector2d& site : sites) points.emplace_back(site.x(), site.y());
  return points;
}

// Sorts [begin, end) with SpatialSortThenInsert; returns what the insertion
// was handed, in order, and expects the pieces to follow each other.
template <class Traits, class Iterator>
auto SortAndCollect(Iterator begin, Iterator end, const Traits& traits) {
  std::vector<typename std::iterator_traits<Iterator>::value_type> inserted;
  Iterator next = begin;
  SpatialSortThenInsert(begin, end, traits, [&](Iterator first, Iterator last) {
    EXPECT_TRUE(first == next) << "a piece skipped or inserted again";
    inserted.insert(inserted.end(), first, last);
    next = last;
  });
  EXPECT_TRUE(next == end) << "the last pieces were not inserted";
  return inserted;
}

TEST(SpatialSortOnPoolTest, PointsInCgalsOrderOnOneAndTwoThreads) {
  for (const int count : {100, 9000, 60000}) {
    const std::vector<site_cgal::Point> input = KernelPoints(MapLikeSites(count, 3));
    std::vector<site_cgal::Point> expected = input;
    CGAL::spatial_sort(expected.begin(), expected.end(), site_cgal::Traits());
    for (const int threads : {1, 2}) {
      const ThreadCount thread_count(threads);
      std::vector<site_cgal::Point> sorted = input;
      const std::vector<site_cgal::Point> inserted =
          SortAndCollect(sorted.begin(), sorted.end(), site_cgal::Traits());
      EXPECT_TRUE(sorted == expected) << count << " points, " << threads << " threads";
      EXPECT_TRUE(inserted == expected) << count << " points, " << threads << " threads";
    }
  }
}

TEST(SpatialSortOnPoolTest, IndicesInCgalsOrderThroughThePointMapAdapter) {
  const std::vector<site_cgal::Point> points = KernelPoints(MapLikeSites(40000, 5));
  using PointMap = CGAL::Pointer_property_map<site_cgal::Point>::const_type;
  using SortTraits = CGAL::Spatial_sort_traits_adapter_2<site_cgal::Traits, PointMap>;
  const SortTraits traits(CGAL::make_property_map(points), site_cgal::Traits());
  std::vector<size_t> expected(points.size());
  for (size_t i = 0; i < expected.size(); ++i) expected[i] = i;
  std::vector<size_t> sorted = expected;
  CGAL::spatial_sort(expected.begin(), expected.end(), traits);
  const ThreadCount thread_count(2);
  EXPECT_EQ(SortAndCollect(sorted.begin(), sorted.end(), traits), expected);
  EXPECT_EQ(sorted, expected);
}

// The faces' vertex positions in container order, and the vertices' infos.
struct Faces {
  std::vector<double> coordinates;
  std::vector<int> infos;
  bool operator==(const Faces& other) const {
    return coordinates == other.coordinates && infos == other.infos;
  }
};

Faces FacesOf(const site_cgal::Delaunay& dt) {
  Faces faces;
  for (auto face = dt.all_faces_begin(); face != dt.all_faces_end(); ++face) {
    for (int i = 0; i < 3; ++i) {
      if (dt.is_infinite(face->vertex(i))) {
        faces.coordinates.push_back(-1e300);
        continue;
      }
      faces.coordinates.push_back(face->vertex(i)->point().x());
      faces.coordinates.push_back(face->vertex(i)->point().y());
    }
  }
  for (auto vertex = dt.finite_vertices_begin(); vertex != dt.finite_vertices_end(); ++vertex) {
    faces.infos.push_back(vertex->info());
  }
  return faces;
}

TEST(SpatialSortOnPoolTest, TriangulationsAreCgalsRangeInsertFaceByFace) {
  const std::vector<Eigen::Vector2d> sites = MapLikeSites(30000, 9);
  const std::vector<site_cgal::Point> points = KernelPoints(sites);
  site_cgal::Delaunay plain;
  plain.insert(points.begin(), points.end());
  std::vector<std::pair<site_cgal::Point, int>> indexed;
  for (size_t i = 0; i < points.size(); ++i) indexed.emplace_back(points[i], static_cast<int>(i));
  site_cgal::Delaunay plain_indexed;
  plain_indexed.insert(indexed.begin(), indexed.end());
  const Faces expected = FacesOf(plain), expected_indexed = FacesOf(plain_indexed);
  for (const int threads : {1, 2}) {
    const ThreadCount thread_count(threads);
    EXPECT_EQ(FacesOf(TriangulateSites(sites)->dt).coordinates, expected.coordinates) << threads;
    EXPECT_TRUE(FacesOf(TriangulateIndexedSites(sites)->dt) == expected_indexed) << threads;
  }
}

}  // namespace
}  // namespace areagraph
