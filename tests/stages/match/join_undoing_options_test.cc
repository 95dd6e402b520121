// Match 4's join undoing: a cut that crosses a passage's border cuts the
// passage too (match pass UNDO_JOINS_ACROSS_PASSAGES), a previous area only partly
// inside the joined area is cut out as well (match.min_overlap), and
// the stretches of a cut that run along a wall noise moved do not count as
// opening (split_joins_wall_margin_m).
#include <gtest/gtest.h>

#include <algorithm>

#include "stages/match/join_undoing.h"
#include "tests/stages/match/synthetic_graphs.h"

namespace areagraph::testing {
namespace {

// A passage between areas a and b along `border` (area a on its left).
void AddBorderPassage(proto::AreaGraph& graph, int a, int b,
                      const std::vector<std::pair<double, double>>& border) {
  AddPassage(graph, a, b, (border.front().first + border.back().first) / 2,
             (border.front().second + border.back().second) / 2);
  proto::Passage* passage = graph.mutable_passages(graph.passages_size() - 1);
  for (const auto& [x, y] : border) {
    proto::Point2* p = passage->add_border_m();
    p->set_x(x);
    p->set_y(y);
  }
  *passage->mutable_segment_m()->mutable_a() = passage->border_m(0);
  *passage->mutable_segment_m()->mutable_b() = passage->border_m(passage->border_m_size() - 1);
}

// Previous version: rooms A [0,4] and B [4,6] (3 m deep) open to each other
// over their whole border (or, with `door_m`, through a door that wide), a
// corridor C above both, open to both along their tops. Ids 0, 1, 2.
// `frame_origin_y` moves the grid down (room for a wall that moves below
// y = 0).
proto::AreaGraph PreviousVersion(double door_m = 0, double frame_origin_y = 0) {
  proto::AreaGraph merged =
      RectGraph(Frame(140, 140, 0, frame_origin_y), {{0, 0, 4, 3}, {4, 0, 6, 3}, {0, 3, 6, 5}});
  if (door_m > 0) {
    AddPassage(merged, 0, 1, 4, 1.5);
    merged.mutable_passages(0)->set_width_m(door_m);
  } else {
    AddBorderPassage(merged, 0, 1, {{4, 0}, {4, 3}});
  }
  AddBorderPassage(merged, 0, 2, {{4, 3}, {0, 3}});
  AddBorderPassage(merged, 1, 2, {{6, 3}, {4, 3}});
  return MatchAfter(merged, nullptr);
}

proto::MatchOptions Options(const std::string& which, double value) {
  proto::MatchOptions options;
  options.set_split_joins_below_m2(20);
  if (which == "across" && value == 0) {
    options.add_skip_passes(proto::MatchOptions::UNDO_JOINS_ACROSS_PASSAGES);
  }
  if (which == "share") options.set_min_overlap(value);
  if (which == "margin") options.set_split_joins_wall_margin_m(value);
  return options;
}

const proto::Passage* PassageBetween(const proto::AreaGraph& graph, int id_a, int id_b) {
  for (const proto::Passage& passage : graph.passages()) {
    const int a = graph.areas(passage.area_a()).stable_id();
    const int b = graph.areas(passage.area_b()).stable_id();
    if (std::min(a, b) == std::min(id_a, id_b) && std::max(a, b) == std::max(id_a, id_b)) {
      return &passage;
    }
  }
  return nullptr;
}

TEST(JoinUndoingOptionsTest, ACutAcrossAPassageCutsThePassageToo) {
  const proto::AreaGraph previous = PreviousVersion();
  // Merge joined A and B; the joined area is open to C along its whole top.
  proto::AreaGraph joined = RectGraph(Frame(140, 140), {{0, 0, 6, 3}, {0, 3, 6, 5}});
  AddBorderPassage(joined, 0, 1, {{6, 3}, {0, 3}});
  const proto::AreaGraph matched = MatchAfter(joined, &previous, Options("across", 1));
  EXPECT_EQ(AreaIds(matched), (Ids{0, 2, 1}));
  ASSERT_EQ(matched.passages_size(), 3);
  // The top opening is cut at x = 4: A keeps 4 m of it, B gets the other 2 m,
  // and each takes back the id of its previous passage to the corridor.
  const proto::Passage* a_c = PassageBetween(matched, 0, 2);
  const proto::Passage* b_c = PassageBetween(matched, 1, 2);
  ASSERT_NE(a_c, nullptr);
  ASSERT_NE(b_c, nullptr);
  EXPECT_EQ(a_c->stable_id(), previous.passages(1).stable_id());
  EXPECT_EQ(b_c->stable_id(), previous.passages(2).stable_id());
  EXPECT_NEAR(a_c->width_m(), 4, 1e-9);
  EXPECT_NEAR(b_c->width_m(), 2, 1e-9);
  ASSERT_NE(PassageBetween(matched, 0, 1), nullptr);
  // The corridor's ring got the cut's vertex, so both passages' borders are its vertices.
  const proto::Ring& corridor = matched.areas(1).polygon_m().outer();
  EXPECT_TRUE(std::any_of(corridor.points().begin(), corridor.points().end(),
                          [](const proto::Point2& p) { return p.x() == 4 && p.y() == 3; }));
  // Match 3 refused such a cut: the join stood and B's id was gone.
  EXPECT_EQ(AreaIds(MatchAfter(joined, &previous, Options("across", 0))), (Ids{0, 2}));
}

TEST(JoinUndoingOptionsTest, AnAreaPartlyInsideTheJoinIsCutOutAboveTheShare) {
  const proto::AreaGraph previous = PreviousVersion();
  // The joined area reaches only 1.2 m into B (60 % of B); the rest of B is
  // no area now (say furniture).
  proto::AreaGraph joined = RectGraph(Frame(140, 140), {{0, 0, 5.2, 3}, {0, 3, 6, 5}});
  AddPassage(joined, 0, 1, 2, 3);
  const proto::AreaGraph matched = MatchAfter(joined, &previous, Options("share", 0.5));
  ASSERT_EQ(AreaIds(matched), (Ids{0, 2, 1}));
  EXPECT_NEAR(matched.areas(2).area_m2(), 3.6, 1e-9);
  EXPECT_EQ(AreaIds(MatchAfter(joined, &previous, Options("share", 0.9))), (Ids{0, 2}));
}

TEST(JoinUndoingOptionsTest, ACutAlongAMovedWallIsNoOpening) {
  // A 1 m opening: the 3 m cut at x = 4 is within 4 x of it.
  const proto::AreaGraph previous = PreviousVersion(1, -1);
  // The joined area's floor wall moved down by a cell (0.05 m), so the cut
  // along B's previous border also runs 2 m along that wall.
  proto::AreaGraph joined = RectGraph(Frame(140, 140, 0, -1), {{0, -0.05, 6, 3}, {0, 3, 6, 5}});
  AddPassage(joined, 0, 1, 2, 3);
  AddPassage(joined, 0, 1, 5, 3);
  EXPECT_EQ(AreaIds(MatchAfter(joined, &previous, Options("margin", 0.1))), (Ids{0, 2, 1}));
  // Counting the 2 m along the wall, 5 m > 4 x 1 m: match 3 left the join.
  EXPECT_EQ(AreaIds(MatchAfter(joined, &previous, Options("margin", 0))), (Ids{0, 2}));
}

TEST(JoinUndoingOptionsTest, AnAreaThatSwallowedTwoGivesBothBack) {
  // B [0,2], A [2,5] and D [5,7] in a row, each open to the next, under a
  // corridor; now merge joined all three.
  proto::AreaGraph merged = RectGraph(Frame(160, 120), {{0, 0, 2, 3}, {2, 0, 5, 3}, {5, 0, 7, 3}});
  AddBorderPassage(merged, 1, 0, {{2, 3}, {2, 0}});
  AddBorderPassage(merged, 1, 2, {{5, 0}, {5, 3}});
  const proto::AreaGraph previous = MatchAfter(merged, nullptr);
  const proto::AreaGraph joined = RectGraph(Frame(160, 120), {{0, 0, 7, 3}});
  // Each round cuts one previous area out of the joined one; rounds run
  // until none is left to cut (one round gave back only one of the two).
  const proto::AreaGraph matched = MatchAfter(joined, &previous, Options("", 0));
  ASSERT_EQ(matched.areas_size(), 3);
  std::vector<int> ids = AreaIds(matched);
  std::sort(ids.begin(), ids.end());
  EXPECT_EQ(ids, (Ids{0, 1, 2}));
  EXPECT_EQ(matched.passages_size(), 2);
  EXPECT_EQ(matched.components(), 1);
}

}  // namespace
}  // namespace areagraph::testing
