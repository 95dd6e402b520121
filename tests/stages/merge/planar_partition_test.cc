// The planar partition of a label image: shared border chains, rings built
// from them, hole removal and topology-preserving simplification.
#include "stages/merge/planar_partition.h"

#include <gtest/gtest.h>

#include <set>

#include "stages/geometry/ring_simplicity.h"
#include "stages/merge/area_outlines.h"
#include "stages/merge/border_simplification.h"

namespace areagraph {
namespace {

// Rows of digits (area labels) and dots (no area).
cv::Mat Labels(const std::vector<std::string>& rows) {
  cv::Mat labels(static_cast<int>(rows.size()), static_cast<int>(rows[0].size()), CV_32S);
  for (int r = 0; r < labels.rows; ++r) {
    for (int c = 0; c < labels.cols; ++c)
      labels.at<int>(r, c) = rows[r][c] == '.' ? 0 : rows[r][c] - '0';
  }
  return labels;
}

// The rings of area `label`, traced (not simplified).
std::vector<PointList> Rings(const PlanarPartition& partition, int label) {
  std::vector<PointList> rings;
  const std::vector<PointList> chains = ChainPoints(partition);
  for (const auto& ring : partition.rings[label - 1]) rings.push_back(RingPoints(ring, chains));
  return rings;
}

std::vector<PointList> OutlineRings(const AreaOutline& outline) {
  std::vector<PointList> rings{outline.outer};
  rings.insert(rings.end(), outline.holes.begin(), outline.holes.end());
  return rings;
}

double Area(const AreaOutline& outline) {
  double area = SignedArea(outline.outer);
  for (const PointList& hole : outline.holes) area += SignedArea(hole);
  return area;
}

// Even-odd test against the outer ring and the holes.
bool InsideOutline(const AreaOutline& outline, double x, double y) {
  bool inside = false;
  for (const PointList& ring : OutlineRings(outline)) {
    for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
      const Eigen::Vector2d& a = ring[i];
      const Eigen::Vector2d& b = ring[j];
      if ((a.y() > y) != (b.y() > y) &&
          x < (b.x() - a.x()) * (y - a.y()) / (b.y() - a.y()) + a.x()) {
        inside = !inside;
      }
    }
  }
  return inside;
}

bool HasVertex(const PointList& ring, const Eigen::Vector2d& p) {
  return std::find(ring.begin(), ring.end(), p) != ring.end();
}

TEST(PlanarPartitionTest, OneCellIsItsFourCorners) {
  const PlanarPartition partition = BuildPlanarPartition(Labels({"...", ".1.", "..."}), 1);
  const std::vector<PointList> rings = Rings(partition, 1);
  ASSERT_EQ(rings.size(), 1u);
  ASSERT_EQ(rings[0].size(), 4u);
  EXPECT_DOUBLE_EQ(SignedArea(rings[0]), 1.0);
  for (const Eigen::Vector2d& p : rings[0]) {
    EXPECT_TRUE((p.x() == 1 || p.x() == 2) && (p.y() == 1 || p.y() == 2));
  }
}

TEST(PlanarPartitionTest, RingWithAHoleHasOneHole) {
  const std::vector<PointList> rings =
      Rings(BuildPlanarPartition(Labels({"111", "1.1", "111"}), 1), 1);
  ASSERT_EQ(rings.size(), 2u);
  const bool first_is_outer = SignedArea(rings[0]) > 0;
  EXPECT_DOUBLE_EQ(SignedArea(rings[first_is_outer ? 0 : 1]), 9.0);
  EXPECT_DOUBLE_EQ(SignedArea(rings[first_is_outer ? 1 : 0]), -1.0);
  EXPECT_EQ(rings[first_is_outer ? 0 : 1].size(), 4u);  // collinear corners dropped
  EXPECT_TRUE(RingsAreSimple(rings));
}

TEST(PlanarPartitionTest, ObstacleCellsTouchingAtACornerAreOneWall) {
  // The empty cell (1, 1) touches the outside at the corner (2, 2): the wall
  // passes there, so the area has no hole, and its ring stays simple.
  const std::vector<PointList> rings =
      Rings(BuildPlanarPartition(Labels({"111", "1.1", "11."}), 1), 1);
  ASSERT_EQ(rings.size(), 1u);
  EXPECT_NEAR(SignedArea(rings[0]), 7.0, 0.2);
  EXPECT_TRUE(RingsAreSimple(rings));
}

TEST(PlanarPartitionTest, NeighboursShareEveryBorderChain) {
  const cv::Mat labels = Labels({"11122", "11222", "12222", "11.22"});
  const PlanarPartition partition = BuildPlanarPartition(labels, 2);
  const std::vector<PointList> one = Rings(partition, 1), two = Rings(partition, 2);
  ASSERT_EQ(one.size(), 1u);
  ASSERT_EQ(two.size(), 1u);
  EXPECT_DOUBLE_EQ(SignedArea(one[0]), 8.0);
  EXPECT_DOUBLE_EQ(SignedArea(two[0]), 11.0);
  // The border between 1 and 2 is one chain, walked once by each area in
  // opposite directions, so all its points are vertices of both rings.
  int between = 0;
  for (size_t c = 0; c < partition.chains.size(); ++c) {
    const BorderChain& chain = partition.chains[c];
    if (std::set<int>{chain.left, chain.right} != std::set<int>{1, 2}) continue;
    ++between;
    for (const Eigen::Vector2d& p : chain.points) {
      EXPECT_TRUE(HasVertex(one[0], p) && HasVertex(two[0], p)) << p.transpose();
    }
    int sides = 0;
    for (int label : {1, 2}) {
      for (const ChainSide& side : partition.rings[label - 1][0]) {
        if (side.chain != static_cast<int>(c)) continue;
        ++sides;
        EXPECT_EQ(side.reversed, chain.right != label);
      }
    }
    EXPECT_EQ(sides, 2);
  }
  EXPECT_EQ(between, 1);
}

TEST(PlanarPartitionTest, AreaCellsTouchingAtACornerAreCutApartAndTheOthersMeet) {
  // Area 1 surrounds 2 and 3; at the corner (2, 2) area 1 touches itself
  // diagonally. It is cut off the corner, and 2 and 3 share a short border
  // whose two ends are junctions of all three areas.
  const cv::Mat labels = Labels({"1111", "1121", "1311", "1111"});
  const PlanarPartition partition = BuildPlanarPartition(labels, 3);
  const std::vector<PointList> one = Rings(partition, 1);
  ASSERT_EQ(one.size(), 2u);  // the outer ring and one hole holding 2 and 3
  EXPECT_TRUE(RingsAreSimple(one));
  double total = 0;
  for (int label : {1, 2, 3}) {
    for (const PointList& ring : Rings(partition, label)) total += SignedArea(ring);
  }
  EXPECT_NEAR(total, 16.0, 1e-9);
  int short_borders = 0;
  for (const BorderChain& chain : partition.chains) {
    if (std::set<int>{chain.left, chain.right} != std::set<int>{2, 3}) continue;
    ++short_borders;
    ASSERT_EQ(chain.points.size(), 2u);
    EXPECT_LT((chain.points[0] - chain.points[1]).norm(), 0.2);
    for (const Eigen::Vector2d& p : chain.points) {
      EXPECT_TRUE(HasVertex(Rings(partition, 2)[0], p) && HasVertex(Rings(partition, 3)[0], p));
    }
  }
  EXPECT_EQ(short_borders, 1);
}

TEST(PlanarPartitionTest, SmallObstacleHolesAreDroppedLargeOnesAndAreaHolesStay) {
  // A one-cell speck and a 2 x 2 block inside area 1, and area 2 (one cell)
  // inside area 1 as well.
  const cv::Mat labels = Labels({"1111111", "1.11111", "1111..1", "1211..1", "1111111"});
  const PlanarPartition partition = BuildPlanarPartition(labels, 2);
  const PartitionOutlines kept = SimplifiedOutlines(partition, labels, 0, 0);
  EXPECT_EQ(kept.areas[0].holes.size(), 3u);
  EXPECT_EQ(kept.dropped_holes, 0);
  const PartitionOutlines dropped = SimplifiedOutlines(partition, labels, 0, 2.0);
  EXPECT_EQ(dropped.areas[0].holes.size(), 2u);  // the block and the hole of area 2
  EXPECT_EQ(dropped.dropped_holes, 1);
  EXPECT_DOUBLE_EQ(Area(dropped.areas[0]), 35 - 4 - 1);
  // Even a large minimum never drops the hole that holds area 2.
  const PartitionOutlines all = SimplifiedOutlines(partition, labels, 0, 100.0);
  ASSERT_EQ(all.areas[0].holes.size(), 1u);
  EXPECT_DOUBLE_EQ(SignedArea(all.areas[0].holes[0]), -1.0);
}

// Two areas split along a staircase that runs diagonally across a
// rectangle: simplification straightens the staircase once for both.
TEST(PlanarPartitionTest, SimplifiedNeighboursKeepTheirSharedBorderAndStaySimple) {
  std::vector<std::string> rows;
  for (int r = 0; r < 20; ++r) rows.push_back(std::string(r + 5, '1') + std::string(25 - r, '2'));
  const cv::Mat labels = Labels(rows);
  const PlanarPartition partition = BuildPlanarPartition(labels, 2);
  const std::vector<PointList> traced = ChainPoints(partition);
  const PartitionOutlines outlines = SimplifiedOutlines(partition, labels, 1.0, 0);
  const AreaOutline& one = outlines.areas[0];
  const AreaOutline& two = outlines.areas[1];
  EXPECT_TRUE(RingsAreSimple(OutlineRings(one)));
  EXPECT_TRUE(RingsAreSimple(OutlineRings(two)));
  // The rectangle is still tiled: the areas add up to 600 cells.
  EXPECT_NEAR(Area(one) + Area(two), 600.0, 1e-9);
  // Each area is a quadrilateral: the staircase became one segment.
  EXPECT_EQ(one.outer.size(), 4u);
  EXPECT_EQ(two.outer.size(), 4u);
  int shared = 0;
  for (const Eigen::Vector2d& p : one.outer) shared += HasVertex(two.outer, p);
  EXPECT_EQ(shared, 2);
  // Simplification only drops vertices, and every dropped one stays within
  // the tolerance of what replaced it.
  for (size_t c = 0; c < traced.size(); ++c) {
    const PointList& kept = outlines.chains[c];
    for (const Eigen::Vector2d& p : kept) EXPECT_TRUE(HasVertex(traced[c], p));
    for (const Eigen::Vector2d& p : traced[c]) {
      double nearest = 1e9;
      for (size_t i = 0; i + 1 < kept.size(); ++i) {
        const Eigen::Vector2d ab = kept[i + 1] - kept[i];
        const double t = std::clamp((p - kept[i]).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
        nearest = std::min(nearest, (kept[i] + t * ab - p).norm());
      }
      EXPECT_LE(nearest, 1.0 + 1e-9);
    }
  }
}

TEST(PlanarPartitionTest, SimplificationNeverLetsBordersCross) {
  // A thin area 2 (three cells wide) winds between areas 1 and 3: with
  // a tolerance far above its width, its borders still may not cross.
  std::vector<std::string> rows;
  for (int r = 0; r < 16; ++r) {
    std::string row(24, '1');
    const int at = 4 + (r % 8 < 4 ? r % 8 : 8 - r % 8) * 2;
    for (int c = at; c < at + 3; ++c) row[c] = '2';
    for (int c = at + 3; c < 24; ++c) row[c] = '3';
    rows.push_back(row);
  }
  const cv::Mat labels = Labels(rows);
  const PartitionOutlines outlines =
      SimplifiedOutlines(BuildPlanarPartition(labels, 3), labels, 5.0, 0);
  for (const AreaOutline& outline : outlines.areas) {
    EXPECT_TRUE(RingsAreSimple(OutlineRings(outline)));
    EXPECT_GT(Area(outline), 0);
    EXPECT_LT(outline.outer.size(), 12u);
  }
  // No point of a fine grid lies inside two outlines.
  for (double y = 0.03; y < 16; y += 0.1) {
    for (double x = 0.03; x < 24; x += 0.1) {
      int inside = 0;
      for (const AreaOutline& outline : outlines.areas) inside += InsideOutline(outline, x, y);
      ASSERT_LE(inside, 1) << x << ", " << y;
    }
  }
}

TEST(BorderSimplificationTest, EachChainKeepsItsOwnTolerance) {
  // Two staircases far apart; only the first may lose its steps.
  PointList steps, other;
  for (int i = 0; i < 10; ++i) {
    steps.insert(steps.end(), {{double(i), double(i)}, {i + 1.0, double(i)}});
    other.insert(other.end(), {{double(i), i + 20.0}, {i + 1.0, i + 20.0}});
  }
  const std::vector<PointList> chains{steps, other};
  const std::vector<PointList> simplified = SimplifyBorders(chains, {1.0, 0.0});
  EXPECT_EQ(simplified[0].size(), 2u);
  EXPECT_EQ(simplified[1], other);
  EXPECT_EQ(SimplifyBorders(chains, {0.0, 0.0}), chains);
}

TEST(PlanarPartitionTest, ThinObstaclesAreNotSimplifiedAway) {
  // A one-cell-wide diagonal obstacle of 30 cells inside area 1: a
  // tolerance of 2 px would flatten it to a sliver, so its ring is
  // simplified more finely and keeps at least the minimum hole size.
  std::vector<std::string> rows(34, std::string(34, '1'));
  for (int i = 0; i < 30; ++i) rows[i + 2][i + 2] = '.';
  const cv::Mat labels = Labels(rows);
  const PartitionOutlines outlines =
      SimplifiedOutlines(BuildPlanarPartition(labels, 1), labels, 2.0, 20.0);
  ASSERT_EQ(outlines.areas[0].holes.size(), 1u);
  EXPECT_GE(-SignedArea(outlines.areas[0].holes[0]), 20.0);
  EXPECT_TRUE(RingsAreSimple(OutlineRings(outlines.areas[0])));
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
