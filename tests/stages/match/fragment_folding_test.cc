// Noise fragments: the polygon union of two neighbours, and MatchAreaGraph
// folding a small piece split off a previous area back into it, but not a
// large piece, nor a piece of newly seen space.
#include "stages/match/fragment_folding.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "stages/geometry/ring_area.h"
#include "stages/match/area_graph_matching.h"
#include "stages/match/polygon_union.h"
#include "tests/stages/match/synthetic_graphs.h"

namespace areagraph::testing {
namespace {

// The area of a ring, and of a polygon (outer minus holes).
double RingArea(const proto::Ring& ring) { return std::abs(TwiceSignedArea(ring)) / 2; }
double PolygonArea(const proto::Polygon& polygon) {
  double area = RingArea(polygon.outer());
  for (const proto::Ring& hole : polygon.holes()) area -= RingArea(hole);
  return area;
}

const proto::Polygon& MetrePolygon(const proto::AreaGraph& graph, int area) {
  return graph.areas(area).polygon_m();
}

TEST(PolygonUnionTest, NeighboursSharingAnEdgeBecomeOneRing) {
  const proto::AreaGraph graph = RectGraph(Frame(200, 100), {{0, 0, 4, 4}, {4, 0, 9, 4}});
  proto::Polygon joined;
  ASSERT_TRUE(UnionOfNeighbours(MetrePolygon(graph, 0), MetrePolygon(graph, 1), &joined));
  EXPECT_EQ(joined.holes_size(), 0);
  EXPECT_DOUBLE_EQ(PolygonArea(joined), 36);
  // Both corners on the shared border remain; the border's edge is gone.
  EXPECT_EQ(joined.outer().points_size(), 6);
}

TEST(PolygonUnionTest, RefusesPolygonsThatDoNotShareAnEdge) {
  proto::Polygon joined;
  // Apart, touching at a corner, and along a border without common vertices.
  for (const auto& rects : std::vector<std::vector<WorldRect>>{{{0, 0, 2, 2}, {5, 0, 7, 2}},
                                                               {{0, 0, 2, 2}, {2, 2, 4, 4}},
                                                               {{0, 0, 4, 4}, {4, 1, 6, 3}}}) {
    const proto::AreaGraph graph = RectGraph(Frame(200, 100), rects);
    EXPECT_FALSE(UnionOfNeighbours(MetrePolygon(graph, 0), MetrePolygon(graph, 1), &joined));
  }
  EXPECT_FALSE(joined.has_outer());
}

TEST(PolygonUnionTest, APieceThatFilledAHoleClosesIt) {
  proto::AreaGraph graph = RectGraph(Frame(200, 200), {{0, 0, 6, 6}, {2, 2, 4, 4}});
  // The outer area has the inner one as its hole (the ring the other way).
  const proto::Ring& inner = graph.areas(1).polygon_m().outer();
  proto::Ring* hole = graph.mutable_areas(0)->mutable_polygon_m()->add_holes();
  for (int i = inner.points_size() - 1; i >= 0; --i) *hole->add_points() = inner.points(i);
  proto::Polygon joined;
  ASSERT_TRUE(UnionOfNeighbours(MetrePolygon(graph, 0), MetrePolygon(graph, 1), &joined));
  EXPECT_EQ(joined.holes_size(), 0);
  EXPECT_DOUBLE_EQ(PolygonArea(joined), 36);
}

TEST(FragmentFoldingTest, ASmallPieceSplitOffByNoiseFoldsBackAndCostsNoId) {
  const proto::AreaGraph first = MatchAfter(RectGraph(Frame(200, 100), {{0, 0, 9, 4}}), nullptr);
  // Noise splits off a 6 m2 strip (below the default 8 m2).
  proto::AreaGraph split = RectGraph(Frame(200, 100), {{7.5, 0, 9, 4}, {0, 0, 7.5, 4}});
  AddPassage(split, 0, 1, 7.5, 2);
  const proto::AreaGraph second = MatchAfter(split, &first);
  ASSERT_EQ(second.areas_size(), 1);
  EXPECT_EQ(AreaIds(second), (Ids{0}));
  EXPECT_DOUBLE_EQ(second.areas(0).area_m2(), 36);
  EXPECT_DOUBLE_EQ(PolygonArea(second.areas(0).polygon_m()), 36);
  EXPECT_EQ(second.passages_size(), 0);  // the border it opened is inside the area
  EXPECT_EQ(second.version().next_area_id(), 1);
  // The next update without the split: every id is still there.
  const proto::AreaGraph third = MatchAfter(RectGraph(Frame(200, 100), {{0, 0, 9, 4}}), &second);
  EXPECT_EQ(AreaIds(third), (Ids{0}));
  EXPECT_EQ(third.version().next_area_id(), 1);

  // Without folding, the strip is a new area whose id the next update drops.
  proto::MatchOptions no_folding;
  no_folding.set_fold_fragments_below_m2(0);
  const proto::AreaGraph unfolded = MatchAfter(split, &first, no_folding);
  EXPECT_EQ(AreaIds(unfolded), (Ids{1, 0}));
}

TEST(FragmentFoldingTest, OtherSegmentationOptionsPublishTheirPieces) {
  proto::MatchOptions defaults;
  const proto::AreaGraph first = MatchAreaGraph(RectGraph(Frame(200, 100), {{0, 0, 9, 4}}), nullptr,
                                                VersionLink(), defaults, "options-a");
  EXPECT_EQ(first.version().segmentation_options_digest(), "options-a");
  const proto::AreaGraph split = RectGraph(Frame(200, 100), {{7.5, 0, 9, 4}, {0, 0, 7.5, 4}});
  // The same options as before: noise, folded back.
  EXPECT_EQ(AreaIds(MatchAreaGraph(split, &first, {"k", 2}, defaults, "options-a")), (Ids{0}));
  // A re-run with other options (say a smaller merge.min_area_m2): the piece is theirs.
  const proto::AreaGraph rerun = MatchAreaGraph(split, &first, {"k", 2}, defaults, "options-b");
  EXPECT_EQ(AreaIds(rerun), (Ids{1, 0}));
  EXPECT_EQ(rerun.version().segmentation_options_digest(), "options-b");
}

TEST(FragmentFoldingTest, ALargePieceAndNewlySeenSpaceStayAreasOfTheirOwn) {
  const proto::AreaGraph first = MatchAfter(RectGraph(Frame(400, 100), {{0, 0, 9, 4}}), nullptr);
  // A 12 m2 part (a door closed): a split, the larger part keeps the id.
  const proto::AreaGraph split =
      MatchAfter(RectGraph(Frame(400, 100), {{6, 0, 9, 4}, {0, 0, 6, 4}}), &first);
  EXPECT_EQ(AreaIds(split), (Ids{1, 0}));
  // A 4 m2 room seen for the first time beside the known one.
  const proto::AreaGraph grown =
      MatchAfter(RectGraph(Frame(400, 100), {{0, 0, 9, 4}, {9, 0, 11, 2}}), &first);
  EXPECT_EQ(AreaIds(grown), (Ids{0, 1}));
}

TEST(FragmentFoldingTest, APieceAboveTheLimitStaysHoweverSmallAShareOfItsArea) {
  // A 10 m2 piece off a 90 m2 room: a ninth of it, but above the 8 m2 limit.
  const proto::AreaGraph first = MatchAfter(RectGraph(Frame(400, 200), {{0, 0, 18, 5}}), nullptr);
  proto::AreaGraph split = RectGraph(Frame(400, 200), {{16, 0, 18, 5}, {0, 0, 16, 5}});
  AddPassage(split, 0, 1, 16, 2.5);
  EXPECT_EQ(AreaIds(MatchAfter(split, &first, proto::MatchOptions())), (Ids{1, 0}));
  proto::MatchOptions options;
  options.set_fold_fragments_below_m2(12);  // now it is under the limit
  EXPECT_EQ(AreaIds(MatchAfter(split, &first, options)), (Ids{0}));
}

TEST(FragmentFoldingTest, TheFragmentsPassagesMoveToTheAreaItJoins) {
  proto::AreaGraph previous_graph = RectGraph(Frame(300, 100), {{0, 0, 9, 4}, {9, 0, 13, 4}});
  AddPassage(previous_graph, 0, 1, 9, 2);
  const proto::AreaGraph first = MatchAfter(previous_graph, nullptr);

  // Area 1 is a 6 m2 piece of the old area 0 between it and the old area 1.
  proto::AreaGraph split =
      RectGraph(Frame(300, 100), {{9, 0, 13, 4}, {7.5, 0, 9, 4}, {0, 0, 7.5, 4}});
  AddPassage(split, 2, 1, 7.5, 2);  // inside what was one area
  AddPassage(split, 1, 0, 9, 2);    // the door that was there before
  AddPassage(split, 2, 0, 8, 3.9);  // hypothetical, to see that it stays
  const proto::AreaGraph second = MatchAfter(split, &first);
  ASSERT_EQ(second.areas_size(), 2);
  EXPECT_EQ(AreaIds(second), (Ids{1, 0}));
  ASSERT_EQ(second.passages_size(), 2);
  for (int p = 0; p < 2; ++p) {
    EXPECT_EQ(second.passages(p).id(), p);
    EXPECT_EQ(std::min(second.passages(p).area_a(), second.passages(p).area_b()), 0);
    EXPECT_EQ(std::max(second.passages(p).area_a(), second.passages(p).area_b()), 1);
  }
  // The old door between the same two areas keeps its id.
  EXPECT_EQ(PassageIds(second)[0], 0);
  for (int a = 0; a < 2; ++a) {
    EXPECT_EQ(second.areas(a).id(), a);
    EXPECT_EQ(second.areas(a).passage_ids_size(), 2);
  }
  EXPECT_EQ(second.components(), 1);
}

}  // namespace
}  // namespace areagraph::testing
