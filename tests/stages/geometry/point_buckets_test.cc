// PointBuckets answers "is any stored point near" as a scan over all points.
#include "stages/geometry/point_buckets.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace areagraph {
namespace {

struct Point {
  double x, y;
};

TEST(PointBuckets, KeepsTheSamePointsAsAScanOverAll) {
  // Thinning as ag-cut keeps one door per place: a point is kept when no
  // kept point lies within `reach`; buckets of twice the reach.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-50, 400);
  for (const double reach : {0.5, 3.0, 30.0}) {
    std::vector<Point> points(1500);
    for (Point& p : points) p = {coordinate(random), coordinate(random)};
    points.push_back({std::numeric_limits<double>::quiet_NaN(), 1});
    points.push_back({std::numeric_limits<double>::infinity(), 1});
    std::vector<Point> scanned, bucketed;
    PointBuckets buckets(2 * reach);
    for (const Point& p : points) {
      bool near = false;
      for (const Point& q : scanned) near |= std::hypot(p.x - q.x, p.y - q.y) < reach;
      if (!near) scanned.push_back(p);
      const bool found = buckets.AnyNear(p.x, p.y, [&](int k) {
        return std::hypot(p.x - bucketed[k].x, p.y - bucketed[k].y) < reach;
      });
      if (found) continue;
      buckets.Add(p.x, p.y, static_cast<int>(bucketed.size()));
      bucketed.push_back(p);
    }
    ASSERT_EQ(bucketed.size(), scanned.size()) << reach;
    for (size_t i = 0; i < scanned.size(); ++i) {
      // NaN compares unequal to itself: check it by isnan.
      EXPECT_EQ(std::isnan(bucketed[i].x), std::isnan(scanned[i].x));
      if (!std::isnan(scanned[i].x)) EXPECT_EQ(bucketed[i].x, scanned[i].x);
      EXPECT_EQ(bucketed[i].y, scanned[i].y);
    }
    EXPECT_GT(scanned.size(), 10u);
  }
}

}  // namespace
}  // namespace areagraph
