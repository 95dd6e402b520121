// MatchAreaGraph on rectangles: which ids survive growth, splits, merges,
// a moved frame and reordering, and that an id is never used twice.
#include "stages/match/area_graph_matching.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "common/error.h"
#include "tests/stages/match/synthetic_graphs.h"

namespace areagraph::testing {
namespace {

TEST(AreaGraphMatchingTest, AFirstVersionNumbersAreasAndPassagesInOrder) {
  proto::AreaGraph graph = RectGraph(Frame(200, 100), {{0, 0, 4, 5}, {4, 0, 10, 5}, {0, 0, 1, 1}});
  AddPassage(graph, 0, 1, 4, 2);
  AddPassage(graph, 1, 2, 1, 0.5);
  const proto::AreaGraph first = MatchAfter(graph, nullptr);
  EXPECT_EQ(AreaIds(first), (Ids{0, 1, 2}));
  EXPECT_EQ(PassageIds(first), (Ids{0, 1}));
  EXPECT_EQ(first.version().number(), 1);
  EXPECT_EQ(first.version().predecessor_key(), "");
  EXPECT_EQ(first.version().next_area_id(), 3);
  EXPECT_EQ(first.version().next_passage_id(), 2);
  // Everything else is the merge artifact as it was.
  proto::AreaGraph without = first;
  without.clear_version();
  for (proto::Area& area : *without.mutable_areas()) area.clear_stable_id();
  for (proto::Passage& passage : *without.mutable_passages()) passage.clear_stable_id();
  EXPECT_EQ(without.SerializeAsString(), graph.SerializeAsString());
}

TEST(AreaGraphMatchingTest, TheSameGraphAgainKeepsEveryId) {
  proto::AreaGraph graph = RectGraph(Frame(200, 100), {{0, 0, 4, 5}, {4, 0, 10, 5}});
  AddPassage(graph, 0, 1, 4, 2);
  const proto::AreaGraph first = MatchAfter(graph, nullptr);
  const proto::AreaGraph second = MatchAfter(graph, &first);
  EXPECT_EQ(AreaIds(second), AreaIds(first));
  EXPECT_EQ(PassageIds(second), PassageIds(first));
  EXPECT_EQ(second.version().number(), 2);
  EXPECT_EQ(second.version().predecessor_key(), "previous-key");
  EXPECT_EQ(second.version().next_area_id(), 2);
}

TEST(AreaGraphMatchingTest, AGrownAreaKeepsItsIdAndNewSpaceGetsANewOne) {
  // A room seen in part, then whole, and a corridor found beside it.
  const proto::AreaGraph first = MatchAfter(RectGraph(Frame(200, 100), {{0, 0, 2, 5}}), nullptr);
  const proto::AreaGraph second =
      MatchAfter(RectGraph(Frame(200, 100), {{5, 0, 9, 5}, {0, 0, 5, 5}}), &first);
  EXPECT_EQ(AreaIds(second), (Ids{1, 0}));
  EXPECT_EQ(second.version().next_area_id(), 2);
}

TEST(AreaGraphMatchingTest, ASplitKeepsTheIdOnItsLargestPart) {
  const proto::AreaGraph first = MatchAfter(RectGraph(Frame(200, 100), {{0, 0, 9, 4}}), nullptr);
  // The small part comes first, so index order cannot be what decides.
  const proto::AreaGraph second =
      MatchAfter(RectGraph(Frame(200, 100), {{6, 0, 9, 4}, {0, 0, 6, 4}}), &first);
  EXPECT_EQ(AreaIds(second), (Ids{1, 0}));
}

TEST(AreaGraphMatchingTest, AMergeKeepsTheIdOfItsLargestParent) {
  const proto::AreaGraph first =
      MatchAfter(RectGraph(Frame(200, 100), {{0, 0, 3, 4}, {3, 0, 9, 4}, {9, 0, 10, 4}}), nullptr);
  const proto::AreaGraph second = MatchAfter(RectGraph(Frame(200, 100), {{0, 0, 10, 4}}), &first);
  EXPECT_EQ(AreaIds(second), (Ids{1}));
  EXPECT_EQ(second.version().next_area_id(), 3);
}

TEST(AreaGraphMatchingTest, AnIdIsNeverGivenToAnotherArea) {
  const proto::AreaGraph first =
      MatchAfter(RectGraph(Frame(200, 100), {{0, 0, 4, 4}, {4, 0, 8, 4}}), nullptr);
  // Area 1 is gone (its space unknown again), then new space appears there.
  const proto::AreaGraph second = MatchAfter(RectGraph(Frame(200, 100), {{0, 0, 4, 4}}), &first);
  EXPECT_EQ(AreaIds(second), (Ids{0}));
  EXPECT_EQ(second.version().next_area_id(), 2);
  const proto::AreaGraph third =
      MatchAfter(RectGraph(Frame(200, 100), {{0, 0, 4, 4}, {4, 0, 8, 4}}), &second);
  EXPECT_EQ(AreaIds(third), (Ids{0, 2}));
}

TEST(AreaGraphMatchingTest, AreasMatchInWorldCoordinatesWhenTheGridGrows) {
  // The map grows to the left and down: a bigger grid with another origin.
  const proto::AreaGraph first =
      MatchAfter(RectGraph(Frame(200, 100), {{0, 0, 4, 5}, {4, 0, 10, 5}}), nullptr);
  const proto::AreaGraph second = MatchAfter(
      RectGraph(Frame(300, 200, -5, -5), {{-5, 0, 0, 5}, {4, 0, 10, 5}, {0, 0, 4, 5}}), &first);
  EXPECT_EQ(AreaIds(second), (Ids{2, 1, 0}));
}

TEST(AreaGraphMatchingTest, ASmallOverlapIsNoMatch) {
  // Under half of the smaller area: a different area that happens to touch.
  const proto::AreaGraph first = MatchAfter(RectGraph(Frame(200, 100), {{0, 0, 4, 4}}), nullptr);
  const proto::AreaGraph second = MatchAfter(RectGraph(Frame(200, 100), {{2.5, 0, 9, 4}}), &first);
  EXPECT_EQ(AreaIds(second), (Ids{1}));
  proto::MatchOptions loose;
  loose.set_min_overlap(0.3);
  const proto::AreaGraph with_loose = MatchAreaGraph(RectGraph(Frame(200, 100), {{2.5, 0, 9, 4}}),
                                                     &first, VersionLink{"k", 2}, loose);
  EXPECT_EQ(AreaIds(with_loose), (Ids{0}));
}

TEST(AreaGraphMatchingTest, IdsFollowTheAreasNotTheirOrder) {
  const std::vector<WorldRect> rects = {{0, 0, 3, 4}, {3, 0, 7, 4}, {7, 0, 9, 4}, {0, 4, 9, 6}};
  const proto::AreaGraph first = MatchAfter(RectGraph(Frame(200, 150), rects), nullptr);
  std::vector<WorldRect> reversed(rects.rbegin(), rects.rend());
  const proto::AreaGraph second = MatchAfter(RectGraph(Frame(200, 150), reversed), &first);
  EXPECT_EQ(AreaIds(second), (Ids{3, 2, 1, 0}));
}

TEST(AreaGraphMatchingTest, PassagesKeepTheirIdsByTheirAreasAndPlace) {
  proto::AreaGraph graph = RectGraph(Frame(200, 100), {{0, 0, 4, 4}, {4, 0, 8, 4}, {0, 4, 8, 5}});
  AddPassage(graph, 0, 1, 4, 1);
  AddPassage(graph, 0, 1, 4, 3);  // a second door between the same rooms
  AddPassage(graph, 0, 2, 2, 4);
  const proto::AreaGraph first = MatchAfter(graph, nullptr);
  ASSERT_EQ(PassageIds(first), (Ids{0, 1, 2}));

  proto::AreaGraph next = RectGraph(Frame(200, 100), {{0, 0, 4, 4}, {4, 0, 8, 4}, {0, 4, 8, 5}});
  AddPassage(next, 1, 0, 4, 3.2);  // the second door, areas swapped, moved 0.2 m
  AddPassage(next, 0, 1, 4, 0.9);  // the first door
  AddPassage(next, 0, 2, 6, 4);    // between the same areas but 4 m away: a new one
  AddPassage(next, 1, 2, 6, 4);    // between other areas: new
  const proto::AreaGraph second = MatchAfter(next, &first);
  EXPECT_EQ(PassageIds(second), (Ids{1, 0, 3, 4}));
  EXPECT_EQ(second.version().next_passage_id(), 5);
}

TEST(AreaGraphMatchingTest, RefusesAPreviousVersionWithoutStableIds) {
  const proto::AreaGraph merge_artifact = RectGraph(Frame(200, 100), {{0, 0, 4, 4}});
  EXPECT_THROW(MatchAfter(merge_artifact, &merge_artifact), InputError);
}

}  // namespace
}  // namespace areagraph::testing
