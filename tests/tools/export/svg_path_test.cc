// Compact SVG path data: what the viewer draws must be the geometry to a
// tenth of a pixel, written as short as the rules allow.
#include "tools/export/svg_path.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "tests/tools/export/svg_path_parser.h"

namespace areagraph {
namespace {

using testing::ParseSvgPath;

TEST(TenthsText, DropsLeadingZerosAndEmptyFractions) {
  EXPECT_EQ(TenthsText(0), "0");
  EXPECT_EQ(TenthsText(5), ".5");
  EXPECT_EQ(TenthsText(-5), "-.5");
  EXPECT_EQ(TenthsText(10), "1");
  EXPECT_EQ(TenthsText(125), "12.5");
  EXPECT_EQ(TenthsText(-20), "-2");
  EXPECT_EQ(TenthsText(-123456), "-12345.6");
}

TEST(SvgPathWriter, WritesRelativeLinesWithoutRepeatedLetters) {
  SvgPathWriter path;
  path.MoveTo(10, 20.5);
  path.LineTo(11, 20);
  path.LineTo(11, 20);  // nothing to draw
  path.LineTo(13.04, 20);
  path.Close();
  EXPECT_EQ(path.text(), "M10 20.5l1-.5 2 0z");
}

TEST(SvgPathWriter, ContinueAtStartsASubpathOnlyWhereTheLastOneEnded) {
  SvgPathWriter path;
  path.ContinueAt(0, 0);
  path.LineTo(1, 0);
  path.ContinueAt(1, 0);
  path.LineTo(2, 0);
  path.ContinueAt(5, 5);
  path.LineTo(5, 6);
  EXPECT_EQ(path.text(), "M0 0l1 0 1 0M5 5l0 1");
  path.Close();
  path.ContinueAt(5, 5);  // after z the point is unknown to the writer: a new M
  EXPECT_EQ(path.text(), "M0 0l1 0 1 0M5 5l0 1zM5 5");
}

TEST(SvgPathWriter, LongPolylinesReadBackWithinATwentiethOfAPixel) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> step(-3, 3);
  proto::Ring ring;
  double x = 1000, y = 2000;
  for (int i = 0; i < 5000; ++i) {
    proto::Point2* point = ring.add_points();
    point->set_x(x += 0.3 + std::abs(step(random)));  // never a step that rounds to nothing
    point->set_y(y += step(random));
  }
  const auto subpaths = ParseSvgPath(RingPath(ring));
  ASSERT_EQ(subpaths.size(), 1u);
  ASSERT_EQ(subpaths[0].size(), 5001u);  // closed: back to the start
  for (int i = 0; i < ring.points_size(); ++i) {
    // Relative steps are taken between rounded points, so errors do not add up.
    EXPECT_NEAR(subpaths[0][i].x, ring.points(i).x(), 0.05 + 1e-9) << i;
    EXPECT_NEAR(subpaths[0][i].y, ring.points(i).y(), 0.05 + 1e-9) << i;
  }
}

TEST(PolygonPath, HolesAreSubpathsAndDegenerateRingsAreLeftOut) {
  proto::Polygon polygon;
  for (const auto& [x, y] : {std::pair{0, 0}, {10, 0}, {10, 10}, {0, 10}}) {
    proto::Point2* point = polygon.mutable_outer()->add_points();
    point->set_x(x);
    point->set_y(y);
  }
  proto::Ring* hole = polygon.add_holes();
  for (const auto& [x, y] : {std::pair{2, 2}, {2, 4}, {4, 4}}) {
    proto::Point2* point = hole->add_points();
    point->set_x(x);
    point->set_y(y);
  }
  polygon.add_holes()->add_points();  // one point: no ring
  EXPECT_EQ(PolygonPath(polygon), "M0 0l10 0 0 10-10 0zM2 2l0 2 2 0z");
}

}  // namespace
}  // namespace areagraph
