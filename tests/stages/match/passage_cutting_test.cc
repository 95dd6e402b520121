// A passage whose border a join's cut crosses is cut in two: the longer
// stretch keeps it (and where it was), a long enough other stretch becomes a
// passage of its own, a stub shorter than a robot's width is dropped.
#include "stages/match/passage_cutting.h"

#include <gtest/gtest.h>

namespace areagraph {
namespace {

// clean.robot_width_m's default, which the Area Graph carries to match.
constexpr double kRobotWidthM = 0.5;

// A passage along the straight border (0, 0) -> (length, 0), point at x.
proto::Passage StraightPassage(double length, double point_x) {
  proto::Passage passage;
  passage.set_area_a(3);
  passage.set_area_b(7);
  passage.set_stable_id(12);
  passage.set_width_m(length);
  passage.mutable_point_m()->set_x(point_x);
  for (double x : {0.0, length}) {
    proto::Point2* p = passage.add_border_m();
    p->set_x(x);
    p->set_y(0);
  }
  return passage;
}

TEST(PassageCuttingTest, TheLongerStretchKeepsThePassageAndTheOtherGetsOne) {
  const std::vector<proto::Passage> pieces =
      CutPassage(StraightPassage(3, 2), {{1, 0}}, kRobotWidthM);
  ASSERT_EQ(pieces.size(), 2u);
  // In border order: [0, 1] then [1, 3]; the second is longer and keeps the point and id.
  EXPECT_EQ(pieces[0].border_m_size(), 2);
  EXPECT_EQ(pieces[0].border_m(1).x(), 1);
  EXPECT_NEAR(pieces[0].width_m(), 1, 1e-12);
  EXPECT_NEAR(pieces[0].point_m().x(), 0.5, 1e-12);
  EXPECT_FALSE(pieces[0].has_stable_id());
  EXPECT_EQ(pieces[1].border_m(0).x(), 1);
  EXPECT_EQ(pieces[1].segment_m().a().x(), 1);
  EXPECT_EQ(pieces[1].segment_m().b().x(), 3);
  EXPECT_NEAR(pieces[1].width_m(), 2, 1e-12);
  EXPECT_EQ(pieces[1].point_m().x(), 2);
  EXPECT_EQ(pieces[1].stable_id(), 12);
  for (const proto::Passage& piece : pieces) {
    EXPECT_EQ(piece.area_a(), 3);  // the caller moves them to their pieces
    EXPECT_EQ(piece.area_b(), 7);
  }
}

TEST(PassageCuttingTest, AStubShorterThanARobotIsDropped) {
  const std::vector<proto::Passage> pieces =
      CutPassage(StraightPassage(3, 2), {{0.3, 0}}, kRobotWidthM);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_EQ(pieces[0].border_m(0).x(), 0.3);
  EXPECT_EQ(pieces[0].border_m(1).x(), 3);
  // For a narrower robot the stub is a passage of its own.
  EXPECT_EQ(CutPassage(StraightPassage(3, 2), {{0.3, 0}}, 0.2).size(), 2u);
}

TEST(PassageCuttingTest, TwoCutsGiveThreeStretches) {
  const std::vector<proto::Passage> pieces =
      CutPassage(StraightPassage(4, 2), {{3, 0}, {1, 0}}, kRobotWidthM);
  ASSERT_EQ(pieces.size(), 3u);
  EXPECT_EQ(pieces[0].border_m(1).x(), 1);
  EXPECT_EQ(pieces[1].border_m(0).x(), 1);
  EXPECT_EQ(pieces[1].border_m(1).x(), 3);
  EXPECT_EQ(pieces[2].border_m(0).x(), 3);
}

TEST(PassageCuttingTest, ACutOffTheBorderIsRefused) {
  EXPECT_TRUE(CutPassage(StraightPassage(3, 2), {{1, 0.5}}, kRobotWidthM).empty());
  // An end, not inside an edge.
  EXPECT_TRUE(CutPassage(StraightPassage(3, 2), {{0, 0}}, kRobotWidthM).empty());
}

}  // namespace
}  // namespace areagraph
