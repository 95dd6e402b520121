// Area outlines traced along cell edges, and the ring simplicity check.
#include <gtest/gtest.h>

#include "stages/geometry/ring_simplicity.h"
#include "stages/merge/region_outline.h"

namespace areagraph {
namespace {

cv::Mat Labels(const std::vector<std::string>& rows) {
  cv::Mat labels(static_cast<int>(rows.size()), static_cast<int>(rows[0].size()), CV_32S);
  for (int r = 0; r < labels.rows; ++r) {
    for (int c = 0; c < labels.cols; ++c)
      labels.at<int>(r, c) = rows[r][c] == '.' ? 0 : rows[r][c] - '0';
  }
  return labels;
}

RegionOutline Trace(const cv::Mat& labels, int label) {
  return TraceRegionOutline(labels, label, cv::Rect(0, 0, labels.cols, labels.rows));
}

std::vector<PointList> Rings(const RegionOutline& outline) {
  std::vector<PointList> rings{outline.outer};
  rings.insert(rings.end(), outline.holes.begin(), outline.holes.end());
  return rings;
}

TEST(RegionOutlineTest, OneCellIsItsFourCorners) {
  const RegionOutline outline = Trace(Labels({"...", ".1.", "..."}), 1);
  ASSERT_EQ(outline.outer.size(), 4u);
  EXPECT_TRUE(outline.holes.empty());
  EXPECT_DOUBLE_EQ(SignedArea(outline.outer), 1.0);
  for (const Eigen::Vector2d& p : outline.outer) {
    EXPECT_TRUE((p.x() == 1 || p.x() == 2) && (p.y() == 1 || p.y() == 2));
  }
}

TEST(RegionOutlineTest, RingWithAHoleHasOneHole) {
  const RegionOutline outline = Trace(Labels({"111", "1.1", "111"}), 1);
  ASSERT_EQ(outline.holes.size(), 1u);
  EXPECT_DOUBLE_EQ(SignedArea(outline.outer), 9.0);
  EXPECT_DOUBLE_EQ(SignedArea(outline.holes[0]), -1.0);
  EXPECT_EQ(outline.outer.size(), 4u);  // collinear corners dropped
  EXPECT_TRUE(RingsAreSimple(Rings(outline)));
}

TEST(RegionOutlineTest, CellsTouchingAtACornerGiveASimpleRing) {
  // The hole at (1, 1) touches the outside at the corner (2, 2) only.
  const RegionOutline outline = Trace(Labels({"111", "1.1", "11."}), 1);
  EXPECT_TRUE(outline.holes.empty());
  EXPECT_NEAR(SignedArea(outline.outer), 7.0, 0.01);
  EXPECT_TRUE(RingsAreSimple(Rings(outline)));
}

TEST(RegionOutlineTest, NeighboursShareTheirBorderAndAreasAreCellCounts) {
  const cv::Mat labels = Labels({"11122", "11222", "12222", "11.22"});
  const RegionOutline one = Trace(labels, 1), two = Trace(labels, 2);
  EXPECT_DOUBLE_EQ(SignedArea(one.outer), 8.0);
  EXPECT_DOUBLE_EQ(SignedArea(two.outer), 11.0);
  // Every corner of region 1 that is not on the map edge or the empty cell
  // is a corner of region 2 too.
  for (const Eigen::Vector2d& p : one.outer) {
    if (p.x() == 0 || p.y() == 0 || p.y() == 4 || (p.x() >= 2 && p.y() >= 3)) continue;
    EXPECT_NE(std::find(two.outer.begin(), two.outer.end(), p), two.outer.end()) << p.transpose();
  }
}

TEST(RegionOutlineTest, SimplifiedStaircaseStaysSimpleAndKeepsCellCentres) {
  std::vector<std::string> rows;
  for (int r = 0; r < 12; ++r) rows.push_back(std::string(r + 1, '1') + std::string(12 - r, '.'));
  const cv::Mat labels = Labels(rows);
  const RegionOutline traced = Trace(labels, 1);
  const RegionOutline simplified = SimplifyOutline(traced, 0.45);
  EXPECT_LT(simplified.outer.size(), traced.outer.size());
  EXPECT_TRUE(RingsAreSimple(Rings(simplified)));
  // Cell centres stay on their side of the simplified outline.
  auto inside = [&](double x, double y) {
    bool in = false;
    const PointList& ring = simplified.outer;
    for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
      if ((ring[i].y() > y) != (ring[j].y() > y) &&
          x < (ring[j].x() - ring[i].x()) * (y - ring[i].y()) / (ring[j].y() - ring[i].y()) +
                  ring[i].x()) {
        in = !in;
      }
    }
    return in;
  };
  for (int r = 0; r < labels.rows; ++r) {
    for (int c = 0; c < labels.cols; ++c) {
      EXPECT_EQ(inside(c + 0.5, r + 0.5), labels.at<int>(r, c) == 1) << c << "," << r;
    }
  }
}

TEST(RingSimplicityTest, TellsSimpleRingsFromOthers) {
  const PointList square{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  const PointList hole{{1, 1}, {1, 2}, {2, 2}, {2, 1}};
  EXPECT_TRUE(RingsAreSimple({square}));
  EXPECT_TRUE(RingsAreSimple({square, hole}));
  EXPECT_FALSE(RingsAreSimple({{{0, 0}, {4, 4}, {4, 0}, {0, 4}}}));                  // bow tie
  EXPECT_FALSE(RingsAreSimple({{{0, 0}, {4, 0}, {2, 0}, {2, 3}}}));                  // folds back
  EXPECT_FALSE(RingsAreSimple({{{0, 0}, {2, 2}, {4, 0}, {4, 4}, {2, 2}, {0, 4}}}));  // touches
  EXPECT_FALSE(RingsAreSimple({square, {{3, 3}, {3, 5}, {5, 5}, {5, 3}}}));          // hole crosses
  EXPECT_FALSE(RingsAreSimple({{{0, 0}, {1, 1}}}));                                  // too short
}

}  // namespace
}  // namespace areagraph
