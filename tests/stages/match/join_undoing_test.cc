// Joins undone: ag-merge joining two areas of the previous version that were
// apart (room joining under scan noise) is cut apart again along the previous
// border, and the swallowed area keeps its id; the neighbours keep sharing
// their border vertex for vertex, and the passages go where they belong.
#include "stages/match/join_undoing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "stages/match/area_graph_matching.h"
#include "stages/match/polygon_union.h"
#include "tests/stages/match/synthetic_graphs.h"

namespace areagraph::testing {
namespace {

bool HasVertex(const proto::Ring& ring, double x, double y) {
  return std::any_of(ring.points().begin(), ring.points().end(),
                     [&](const proto::Point2& p) { return p.x() == x && p.y() == y; });
}

// Previous version: rooms A [0,4] and B [4,6] side by side, open to each
// other over `opening_m` of their 3 m border, a corridor C above both,
// passages A-B, A-C and B-C. Ids 0, 1, 2.
proto::AreaGraph PreviousVersion(double opening_m = 3) {
  return MatchAfter(TwoRoomsUnderACorridor(3, opening_m), nullptr);
}

// Now merge joined A and B into one area, with both passages to C.
proto::AreaGraph JoinedUpdate() { return TwoRoomsJoined(3); }

proto::MatchOptions SplitBelow(double m2) {
  proto::MatchOptions options;
  options.set_split_joins_below_m2(m2);
  return options;
}

int IndexOfId(const proto::AreaGraph& graph, int id) {
  for (int i = 0; i < graph.areas_size(); ++i) {
    if (graph.areas(i).stable_id() == id) return i;
  }
  return -1;
}

TEST(JoinUndoingTest, AJoinOfTwoPreviousAreasIsCutApartAndBothKeepTheirIds) {
  const proto::AreaGraph previous = PreviousVersion();
  const proto::AreaGraph matched = MatchAfter(JoinedUpdate(), &previous, SplitBelow(20));
  ASSERT_EQ(matched.areas_size(), 3);
  EXPECT_EQ(AreaIds(matched), (Ids{0, 2, 1}));  // A's rest, the corridor, B again
  const proto::Area& a = matched.areas(IndexOfId(matched, 0));
  const proto::Area& b = matched.areas(IndexOfId(matched, 1));
  EXPECT_NEAR(a.area_m2(), 12, 1e-9);
  EXPECT_NEAR(b.area_m2(), 6, 1e-9);
  EXPECT_NEAR(b.centroid_m().x(), 5, 1e-9);
  EXPECT_EQ(matched.version().next_area_id(), 3);  // no new id given out
}

TEST(JoinUndoingTest, TheCutVertexIsAddedToTheNeighbourSoBordersStillMatch) {
  const proto::AreaGraph previous = PreviousVersion();
  const proto::AreaGraph matched = MatchAfter(JoinedUpdate(), &previous, SplitBelow(20));
  ASSERT_EQ(matched.areas_size(), 3);
  const proto::Area& corridor = matched.areas(IndexOfId(matched, 2));
  EXPECT_TRUE(HasVertex(corridor.polygon_m().outer(), 4, 3));
  EXPECT_EQ(corridor.polygon_px().outer().points_size(),
            corridor.polygon_m().outer().points_size());
  // Vertex for vertex: the corridor joins each piece by a shared edge.
  proto::Polygon joined;
  EXPECT_TRUE(UnionOfNeighbours(corridor.polygon_m(),
                                matched.areas(IndexOfId(matched, 1)).polygon_m(), &joined));
  EXPECT_TRUE(UnionOfNeighbours(corridor.polygon_m(),
                                matched.areas(IndexOfId(matched, 0)).polygon_m(), &joined));
}

TEST(JoinUndoingTest, PassagesGoToTheirPieceAndTheOldPassageComesBack) {
  const proto::AreaGraph previous = PreviousVersion();
  const proto::AreaGraph matched = MatchAfter(JoinedUpdate(), &previous, SplitBelow(20));
  ASSERT_EQ(matched.passages_size(), 3);
  ASSERT_EQ(matched.areas_size(), 3);
  // Every passage of the previous version is back, with its id, between the
  // same stable areas.
  for (const proto::Passage& old : previous.passages()) {
    const auto found =
        std::find_if(matched.passages().begin(), matched.passages().end(),
                     [&](const proto::Passage& p) { return p.stable_id() == old.stable_id(); });
    ASSERT_NE(found, matched.passages().end()) << "passage " << old.stable_id();
    std::vector<int> before = {previous.areas(old.area_a()).stable_id(),
                               previous.areas(old.area_b()).stable_id()};
    std::vector<int> now = {matched.areas(found->area_a()).stable_id(),
                            matched.areas(found->area_b()).stable_id()};
    std::sort(before.begin(), before.end());
    std::sort(now.begin(), now.end());
    EXPECT_EQ(before, now);
  }
  // The passage between the pieces runs along their shared border.
  const auto between = std::find_if(matched.passages().begin(), matched.passages().end(),
                                    [&](const proto::Passage& p) {
                                      return matched.areas(p.area_a()).stable_id() != 2 &&
                                             matched.areas(p.area_b()).stable_id() != 2;
                                    });
  ASSERT_NE(between, matched.passages().end());
  ASSERT_EQ(between->border_m_size(), 2);
  EXPECT_EQ(between->border_m(0).x(), 4);
  EXPECT_EQ(between->border_m(1).x(), 4);
  EXPECT_EQ(matched.components(), 1);
}

TEST(JoinUndoingTest, OffByDefaultAboveTheLimitAndForOtherOptions) {
  const proto::AreaGraph previous = PreviousVersion();
  // 0 (the default) publishes merge's join: B's id is gone.
  EXPECT_EQ(AreaIds(MatchAfter(JoinedUpdate(), &previous, SplitBelow(0))), (Ids{0, 2}));
  // B (6 m2) is not below a 5 m2 limit.
  EXPECT_EQ(AreaIds(MatchAfter(JoinedUpdate(), &previous, SplitBelow(5))), (Ids{0, 2}));
  // A predecessor made with other segmentation options: merge's areas as they are.
  VersionLink link{"previous-key", 2};
  EXPECT_EQ(AreaIds(MatchAreaGraph(JoinedUpdate(), &previous, link, SplitBelow(20), "other")),
            (Ids{0, 2}));
}

TEST(JoinUndoingTest, AWallRemovedIsARealJoin) {
  // Before, a 0.6 m door; now the whole 3 m border is open: the cut would be
  // more than kMaxCutPerOpening times the opening, so the join stands.
  const proto::AreaGraph previous = PreviousVersion(0.6);
  EXPECT_EQ(AreaIds(MatchAfter(JoinedUpdate(), &previous, SplitBelow(20))), (Ids{0, 2}));
  // Up to four times the opening is noise moving merge's room joining.
  const proto::AreaGraph wider = PreviousVersion(1.5);
  EXPECT_EQ(AreaIds(MatchAfter(JoinedUpdate(), &wider, SplitBelow(20))), (Ids{0, 2, 1}));
}

TEST(JoinUndoingTest, NoPassageBetweenThePreviousAreasNoSplit) {
  proto::AreaGraph merged = RectGraph(Frame(140, 120), {{0, 0, 4, 3}, {4, 0, 6, 3}, {0, 3, 6, 5}});
  AddPassage(merged, 0, 2, 2, 3);
  AddPassage(merged, 1, 2, 5, 3);
  const proto::AreaGraph previous = MatchAfter(merged, nullptr);
  EXPECT_EQ(AreaIds(MatchAfter(JoinedUpdate(), &previous, SplitBelow(20))), (Ids{0, 2}));
}

TEST(JoinUndoingTest, IdenticalMapsGiveIdenticalIdsWithSplitting) {
  const proto::AreaGraph previous = PreviousVersion();
  const proto::AreaGraph first = MatchAfter(JoinedUpdate(), &previous, SplitBelow(20));
  const proto::AreaGraph again = MatchAfter(JoinedUpdate(), &first, SplitBelow(20));
  EXPECT_EQ(AreaIds(again), AreaIds(first));
}

}  // namespace
}  // namespace areagraph::testing
