// PolygonLabels against FillPolygon one polygon after another.
#include "stages/geometry/polygon_raster.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "tests/support/thread_count.h"

namespace areagraph {
namespace {

using areagraph::testing::ThreadCount;

void AddRing(const std::vector<std::pair<double, double>>& points, proto::Ring* ring) {
  for (const auto& [x, y] : points) {
    proto::Point2* p = ring->add_points();
    p->set_x(x);
    p->set_y(y);
  }
}

// A random star-shaped polygon around (cx, cy), radii up to `radius`, with a
// square hole at its centre when `hole`.
proto::Polygon RandomPolygon(std::mt19937& random, double cx, double cy, double radius, bool hole) {
  std::uniform_real_distribution<double> share(0.3, 1.0);
  std::uniform_int_distribution<int> corners(3, 12);
  const int n = corners(random);
  std::vector<std::pair<double, double>> outer;
  for (int i = 0; i < n; ++i) {
    const double angle = 2 * M_PI * i / n, r = radius * share(random);
    // Half cells and odd fractions, as the cut's polygons have.
    outer.emplace_back(std::round((cx + r * std::cos(angle)) * 8) / 8,
                       std::round((cy + r * std::sin(angle)) * 8) / 8);
  }
  proto::Polygon polygon;
  AddRing(outer, polygon.mutable_outer());
  if (hole) {
    const double h = 0.2 * radius;
    AddRing({{cx - h, cy - h}, {cx - h, cy + h}, {cx + h, cy + h}, {cx + h, cy - h}},
            polygon.add_holes());
  }
  return polygon;
}

cv::Mat FilledInOrder(const std::vector<std::pair<const proto::Polygon*, int>>& polygons,
                      cv::Size size) {
  cv::Mat labels = cv::Mat::zeros(size, CV_32S);
  for (const auto& [polygon, value] : polygons) FillPolygon(*polygon, value, &labels);
  return labels;
}

// Overlapping polygons of several values, some across the image's edges,
// some bigger than the image, a few too small to paint: the same cells on
// one, two and three threads.
TEST(PolygonLabelsTest, EqualsFillPolygonInOrder) {
  std::mt19937 random(16);
  const cv::Size size(700, 500);
  std::uniform_real_distribution<double> x(-30, 730), y(-30, 530), radius(1, 60);
  std::vector<proto::Polygon> polygons;
  for (int i = 0; i < 600; ++i) {
    polygons.push_back(RandomPolygon(random, x(random), y(random), radius(random), i % 5 == 0));
  }
  // Across the whole image, and one whose mask alone is over the chunk's size.
  polygons.push_back(RandomPolygon(random, 350, 250, 500, true));
  proto::Polygon huge;
  AddRing({{-0.5, -0.5}, {4000, 0}, {4000, 3000}, {0, 3000}}, huge.mutable_outer());
  polygons.push_back(huge);
  proto::Polygon degenerate;
  AddRing({{3, 3}, {9, 9}}, degenerate.mutable_outer());
  polygons.push_back(degenerate);
  std::vector<std::pair<const proto::Polygon*, int>> in_order;
  for (size_t i = 0; i < polygons.size(); ++i) {
    // Values that repeat (an area's several polygons), rise and fall: the
    // later polygon wins.
    in_order.emplace_back(&polygons[i], 1 + static_cast<int>((i / 3) * 7 % 50));
  }
  const std::vector<std::pair<const proto::Polygon*, int>>& all = in_order;
  // Without the two that cover everything too: the last would hide the rest.
  const std::vector<std::pair<const proto::Polygon*, int>> partial(in_order.begin(),
                                                                   in_order.end() - 3);
  for (const auto* list : {&partial, &all}) {
    const cv::Mat expected = FilledInOrder(*list, size);
    for (const int threads : {1, 2, 3}) {
      ThreadCount count(threads);
      const cv::Mat labels = PolygonLabels(*list, size);
      ASSERT_EQ(labels.type(), CV_32S);
      EXPECT_EQ(cv::countNonZero(labels != expected), 0)
          << threads << " threads, " << list->size() << " polygons";
    }
  }
}

}  // namespace
}  // namespace areagraph
