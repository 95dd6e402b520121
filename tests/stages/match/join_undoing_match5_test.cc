// Match 5's join undoing, on the kinds of join that lab_e's noise-only
// updates left standing: an id that moved to a small leftover of its area
// (match pass UNDO_JOINS_WHEN_ID_MOVED), a previous outline that touches itself at a
// vertex (WithoutPinches), a door whose passage measured narrower than a
// robot (the Area Graph's robot_width_m), and two areas that shared a border but
// no passage (UNDO_JOINS_WITHOUT_PASSAGE).
#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "stages/common/map_frame.h"
#include "stages/geometry/ring_area.h"
#include "stages/match/ring_pinches.h"
#include "tests/stages/match/synthetic_graphs.h"

namespace areagraph::testing {
namespace {

int IndexOfId(const proto::AreaGraph& graph, int id) {
  for (int i = 0; i < graph.areas_size(); ++i) {
    if (graph.areas(i).stable_id() == id) return i;
  }
  return -1;
}

proto::Ring RingOf(const std::vector<std::pair<double, double>>& points) {
  proto::Ring ring;
  for (const auto& [x, y] : points) {
    proto::Point2* p = ring.add_points();
    p->set_x(x);
    p->set_y(y);
  }
  return ring;
}

// Previous version: rooms A [0,4] and B [4,7] (3 m deep) side by side with a
// door between them, a corridor C [0,7] above both. Ids 0, 1, 2.
proto::AreaGraph RoomsUnderACorridor() {
  proto::AreaGraph merged = RectGraph(Frame(160, 120), {{0, 0, 4, 3}, {4, 0, 7, 3}, {0, 3, 7, 5}});
  AddPassage(merged, 0, 1, 4, 1.5);
  AddPassage(merged, 0, 2, 2, 3);
  AddPassage(merged, 1, 2, 5.5, 3);
  return MatchAfter(merged, nullptr);
}

TEST(JoinUndoingMatch5Test, AnIdThatMovedToALeftoverGoesBackToItsArea) {
  const proto::AreaGraph previous = RoomsUnderACorridor();
  // Merge joined A with two thirds of B; the last third of B, S [6,7], is an
  // area of its own, so B's id went to S (3 of B's 9 m2), as lab_e's
  // corridor piece 23 did at its first noise-only update.
  proto::AreaGraph merged = RectGraph(Frame(160, 120), {{0, 0, 6, 3}, {6, 0, 7, 3}, {0, 3, 7, 5}});
  AddPassage(merged, 0, 1, 6, 1.5);
  AddPassage(merged, 0, 2, 2, 3);
  AddPassage(merged, 1, 2, 6.5, 3);

  proto::MatchOptions match4;
  match4.add_skip_passes(proto::MatchOptions::UNDO_JOINS_WHEN_ID_MOVED);
  const proto::AreaGraph before = MatchAfter(merged, &previous, match4);
  ASSERT_EQ(AreaIds(before), (Ids{0, 1, 2}));
  EXPECT_NEAR(before.areas(IndexOfId(before, 1)).area_m2(), 3, 1e-9);  // B's id on S

  // Match 5: B is cut out of the joined area again and takes its id back;
  // S, a piece of B beside it, folds back into it.
  const proto::AreaGraph matched = MatchAfter(merged, &previous);
  ASSERT_EQ(matched.areas_size(), 3);
  const int b = IndexOfId(matched, 1);
  ASSERT_GE(b, 0);
  EXPECT_NEAR(matched.areas(b).area_m2(), 9, 1e-9);
  double min_x = 1e9, max_x = -1e9;  // B's outline spans [4, 7] again
  for (const proto::Point2& p : matched.areas(b).polygon_m().outer().points()) {
    min_x = std::min(min_x, p.x());
    max_x = std::max(max_x, p.x());
  }
  EXPECT_EQ(min_x, 4);
  EXPECT_EQ(max_x, 7);
  EXPECT_NEAR(matched.areas(IndexOfId(matched, 0)).area_m2(), 12, 1e-9);
  EXPECT_EQ(matched.version().next_area_id(), 3);  // no new id given out
  EXPECT_EQ(matched.components(), 1);
}

TEST(JoinUndoingMatch5Test, APinchedRingKeepsItsLargestLoop) {
  // A 4 m square with a 1 m square touching it at its corner (4, 4).
  proto::Polygon pinched;
  *pinched.mutable_outer() =
      RingOf({{0, 0}, {4, 0}, {4, 4}, {5, 4}, {5, 5}, {4, 5}, {4, 4}, {0, 4}});
  const proto::Polygon repaired = WithoutPinches(pinched);
  EXPECT_EQ(repaired.outer().points_size(), 4);
  EXPECT_NEAR(TwiceSignedArea(repaired.outer()), 32, 1e-9);
  // Starting inside the small loop gives the same loop.
  *pinched.mutable_outer() =
      RingOf({{5, 4}, {5, 5}, {4, 5}, {4, 4}, {0, 4}, {0, 0}, {4, 0}, {4, 4}});
  EXPECT_NEAR(TwiceSignedArea(WithoutPinches(pinched).outer()), 32, 1e-9);
  // A simple ring stays as it is.
  EXPECT_EQ(WithoutPinches(repaired).outer().points_size(), 4);
}

TEST(JoinUndoingMatch5Test, AJoinIsCutAlongAPreviousOutlineThatTouchesItself) {
  proto::AreaGraph previous = RoomsUnderACorridor();
  // B's previous outline had a 0.5 m lobe hanging off its corner (7, 3), as
  // merge's outlines sometimes have: CGAL refuses such a ring as not simple.
  const MapTransform transform(previous.frame());
  const std::vector<std::pair<double, double>> ring = {{4, 0},     {7, 0},   {7, 3}, {7.5, 3},
                                                       {7.5, 3.5}, {7, 3.5}, {7, 3}, {4, 3}};
  proto::Area* b = previous.mutable_areas(1);
  *b->mutable_polygon_m()->mutable_outer() = RingOf(ring);
  std::vector<std::pair<double, double>> pixels;
  for (const auto& [x, y] : ring) {
    const Eigen::Vector2d px = transform.WorldToPixel({x, y});
    pixels.push_back({px.x(), px.y()});
  }
  *b->mutable_polygon_px()->mutable_outer() = RingOf(pixels);
  // Now merge joined A and B.
  proto::AreaGraph merged = RectGraph(Frame(160, 120), {{0, 0, 7, 3}, {0, 3, 7, 5}});
  AddPassage(merged, 0, 1, 2, 3);
  AddPassage(merged, 0, 1, 5.5, 3);
  const proto::AreaGraph matched = MatchAfter(merged, &previous);
  ASSERT_EQ(AreaIds(matched), (Ids{0, 2, 1}));
  EXPECT_NEAR(matched.areas(2).area_m2(), 9, 1e-9);
}

// Rooms A [0,4] and B [4,6], 1.5 m deep, under a corridor C; with a door
// between A and B `door_m` wide, or none.
proto::AreaGraph ShallowRooms(double door_m) {
  return MatchAfter(TwoRoomsUnderACorridor(1.5, door_m), nullptr);
}

proto::AreaGraph ShallowRoomsJoined() { return TwoRoomsJoined(1.5); }

TEST(JoinUndoingMatch5Test, ADoorNarrowerThanARobotCountsAsTheLeastOpening) {
  // The door measured 0.3 m: the 1.5 m cut is over 4 x 0.3 m but within
  // 4 x 0.5 m.
  const proto::AreaGraph previous = ShallowRooms(0.3);
  EXPECT_EQ(AreaIds(MatchAfter(ShallowRoomsJoined(), &previous)), (Ids{0, 2, 1}));
  // Match 4 took the passage as measured (a robot width of 0).
  proto::AreaGraph measured = ShallowRoomsJoined();
  measured.set_robot_width_m(0);
  EXPECT_EQ(AreaIds(MatchAfter(measured, &previous)), (Ids{0, 2}));
  // A wall of 2.5 m between rooms 2.5 m deep is still a real join.
  proto::AreaGraph deep = RectGraph(Frame(140, 100), {{0, 0, 4, 2.5}, {4, 0, 6, 2.5}});
  AddPassage(deep, 0, 1, 4, 1.25);
  deep.mutable_passages(0)->set_width_m(0.3);
  const proto::AreaGraph deep_previous = MatchAfter(deep, nullptr);
  EXPECT_EQ(AreaIds(MatchAfter(RectGraph(Frame(140, 100), {{0, 0, 6, 2.5}}), &deep_previous)),
            (Ids{0}));
}

TEST(JoinUndoingMatch5Test, TwoAreasThatSharedABorderButNoPassageAreCutApart) {
  const proto::AreaGraph previous = ShallowRooms(0);
  const proto::AreaGraph matched = MatchAfter(ShallowRoomsJoined(), &previous);
  ASSERT_EQ(AreaIds(matched), (Ids{0, 2, 1}));
  EXPECT_NEAR(matched.areas(2).area_m2(), 3, 1e-9);
  proto::MatchOptions match4;
  match4.add_skip_passes(proto::MatchOptions::UNDO_JOINS_WITHOUT_PASSAGE);
  EXPECT_EQ(AreaIds(MatchAfter(ShallowRoomsJoined(), &previous, match4)), (Ids{0, 2}));
}

}  // namespace
}  // namespace areagraph::testing
