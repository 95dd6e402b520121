// Where cut pass CUT_NARROW_TAILS cuts a room's edge that runs on into a narrow
// dead-end tail, and where it does not.
#include "stages/cut/narrow_tails.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "tests/stages/cut/straight_edge.h"

namespace areagraph {
namespace {

// Metres per pixel of the constructed edges (the maps' usual).
constexpr double kResolutionM = 0.05;

// A room (clearance 40 px) up to x = `mouth` - 5, narrowing over 5 px to a
// tail of clearance `tail` that runs to the edge's end at x = 100.
std::function<double(double)> RoomWithTail(double mouth, double tail) {
  return [=](double x) {
    if (x >= mouth) return tail;
    if (x <= mouth - 5) return 40.0;
    return tail + (40 - tail) * (mouth - x) / 5;
  };
}

std::vector<EdgePiece> OneRoom(const EdgeTrack& track) { return {{track.Start(), track.End(), 0}}; }

// How many pieces an edge that is all one room becomes.
size_t PiecesOf(const std::function<double(double)>& clearance, bool source_is_dead_end,
                bool target_is_dead_end) {
  const proto::GraphEdge edge = StraightEdge(clearance);
  const EdgeTrack track(edge);
  std::vector<EdgePiece> pieces = OneRoom(track);
  CutNarrowTails(track, source_is_dead_end, target_is_dead_end, kResolutionM, &pieces);
  return pieces.size();
}

TEST(NarrowTailsTest, ALongNarrowTailAtADeadEndIsCutWhereItBegins) {
  const proto::GraphEdge edge = StraightEdge(RoomWithTail(35, 7));
  const EdgeTrack track(edge);
  std::vector<EdgePiece> pieces = OneRoom(track);
  CutNarrowTails(track, false, true, kResolutionM, &pieces);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_EQ(pieces[0].room, 0);
  EXPECT_EQ(pieces[1].room, -1);
  EXPECT_NEAR(track.PointAt(pieces[0].end).x(), 35, 2.01);
  EXPECT_NEAR(track.ArcAt(pieces[1].end), 100, 1e-9);
}

TEST(NarrowTailsTest, ATailAtTheSourceIsCutToo) {
  const auto tail = RoomWithTail(35, 7);
  const proto::GraphEdge edge = StraightEdge([&](double x) { return tail(100 - x); });
  const EdgeTrack track(edge);
  std::vector<EdgePiece> pieces = OneRoom(track);
  CutNarrowTails(track, true, false, kResolutionM, &pieces);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_EQ(pieces[0].room, -1);
  EXPECT_EQ(pieces[1].room, 0);
  EXPECT_NEAR(track.PointAt(pieces[1].begin).x(), 65, 2.01);
}

TEST(NarrowTailsTest, OnlyDeadEndsHaveTails) {
  EXPECT_EQ(PiecesOf(RoomWithTail(35, 7), true, false), 1u);  // the tail leads to a junction
}

TEST(NarrowTailsTest, AShortTailIsANicheOfTheRoom) {
  // 20 px and the clearance beyond the dead end: under 4 widths (56 px).
  EXPECT_EQ(PiecesOf(RoomWithTail(80, 7), false, true), 1u);
}

TEST(NarrowTailsTest, ATailMoreThanHalfAsWideAsTheRoomIsPartOfIt) {
  EXPECT_EQ(PiecesOf(RoomWithTail(35, 21), false, true), 1u);
}

TEST(NarrowTailsTest, ARoomlessEndIsLeftAlone) {
  const proto::GraphEdge edge = StraightEdge(RoomWithTail(35, 7));
  const EdgeTrack track(edge);
  std::vector<EdgePiece> pieces{{track.Start(), track.End(), -1}};
  CutNarrowTails(track, false, true, kResolutionM, &pieces);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_EQ(pieces[0].room, -1);
}

}  // namespace
}  // namespace areagraph
