// SplitPolygonByGuide: cutting a polygon along another's border, with the
// slivers where the guide's border runs just inside the polygon's going to
// the inside, and refusing what CGAL's Boolean operations cannot take.
#include "stages/geometry/polygon_split.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "stages/geometry/ring_area.h"

namespace areagraph {
namespace {

proto::Polygon Ring(const std::vector<std::pair<double, double>>& points) {
  proto::Polygon polygon;
  for (const auto& [x, y] : points) {
    proto::Point2* point = polygon.mutable_outer()->add_points();
    point->set_x(x);
    point->set_y(y);
  }
  return polygon;
}

proto::Polygon Box(double x0, double y0, double x1, double y1) {
  return Ring({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
}

double SignedArea(const proto::Ring& ring) { return TwiceSignedArea(ring) / 2; }

std::set<std::pair<double, double>> Vertices(const proto::Polygon& polygon) {
  std::set<std::pair<double, double>> vertices;
  for (const proto::Point2& p : polygon.outer().points()) vertices.insert({p.x(), p.y()});
  return vertices;
}

TEST(PolygonSplitTest, CutsAlongTheGuideAndBothPiecesShareTheCut) {
  proto::Polygon inside, rest;
  ASSERT_TRUE(SplitPolygonByGuide(Box(0, 0, 4, 4), Box(2, -1, 6, 5), &inside, &rest));
  EXPECT_DOUBLE_EQ(SignedArea(inside.outer()), 8);
  EXPECT_DOUBLE_EQ(SignedArea(rest.outer()), 8);
  const auto a = Vertices(inside), b = Vertices(rest);
  EXPECT_TRUE(a.count({2, 0}) && a.count({2, 4}) && b.count({2, 0}) && b.count({2, 4}));
}

TEST(PolygonSplitTest, SliversOutsideTheGuideGoWithTheInside) {
  // The guide stops a millimetre short of the polygon's right edge: that
  // strip is not part of the largest piece outside it, so it goes inside.
  proto::Polygon inside, rest;
  ASSERT_TRUE(SplitPolygonByGuide(Box(0, 0, 4, 4), Box(2, -1, 3.999, 5), &inside, &rest));
  EXPECT_NEAR(SignedArea(inside.outer()), 8, 1e-9);
  EXPECT_NEAR(SignedArea(rest.outer()), 8, 1e-9);
}

TEST(PolygonSplitTest, PiecesRunLikeTheWhole) {
  proto::Polygon clockwise = Ring({{0, 0}, {0, 4}, {4, 4}, {4, 0}}), inside, rest;
  ASSERT_TRUE(SplitPolygonByGuide(clockwise, Box(2, -1, 6, 5), &inside, &rest));
  EXPECT_LT(SignedArea(inside.outer()), 0);
  EXPECT_LT(SignedArea(rest.outer()), 0);
}

TEST(PolygonSplitTest, RefusesWhatCannotBeSplit) {
  proto::Polygon inside, rest;
  // A bow tie is not simple.
  EXPECT_FALSE(SplitPolygonByGuide(Ring({{0, 0}, {4, 4}, {4, 0}, {0, 4}}), Box(2, -1, 6, 5),
                                   &inside, &rest));
  // A guide that misses the polygon.
  EXPECT_FALSE(SplitPolygonByGuide(Box(0, 0, 4, 4), Box(5, 5, 6, 6), &inside, &rest));
  // A guide that covers the whole leaves no rest; the outputs stay alone.
  EXPECT_FALSE(SplitPolygonByGuide(Box(0, 0, 4, 4), Box(-1, -1, 5, 5), &inside, &rest));
  EXPECT_TRUE(inside.outer().points().empty());
}

}  // namespace
}  // namespace areagraph
