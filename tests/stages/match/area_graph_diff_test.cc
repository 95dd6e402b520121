// DiffAreaGraphs: what a diff reports for splits, merges, growth, new and
// vanished space, and passages, and how it prints.
#include "stages/match/area_graph_diff.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/error.h"
#include "stages/match/area_graph_matching.h"
#include "tests/stages/match/synthetic_graphs.h"

namespace areagraph::testing {
namespace {

Ids ToIds(const google::protobuf::RepeatedField<int32_t>& ids) {
  return Ids(ids.begin(), ids.end());
}

proto::AreaGraph Next(const proto::AreaGraph& current, const proto::AreaGraph* previous) {
  VersionLink link;
  if (previous != nullptr) link = {"k", previous->version().number() + 1};
  return MatchAreaGraph(current, previous, link, proto::MatchOptions());
}

TEST(AreaGraphDiffTest, ReportsSplitsMergesGrowthAndNewSpace) {
  // 0 | 1 | 2 side by side, and 3 below; then 0 splits (its right third
  // becomes area 4), 1 and 2 merge, 3 grows, and 5 appears in new space.
  proto::AreaGraph before_graph =
      RectGraph(Frame(400, 200), {{0, 0, 6, 4}, {6, 0, 10, 4}, {10, 0, 12, 4}, {0, 4, 12, 6}});
  AddPassage(before_graph, 0, 1, 6, 2);
  AddPassage(before_graph, 1, 2, 10, 2);
  AddPassage(before_graph, 0, 3, 3, 4);
  const proto::AreaGraph before = Next(before_graph, nullptr);
  proto::AreaGraph after_graph = RectGraph(
      Frame(400, 200), {{0, 0, 4, 4}, {4, 0, 6, 4}, {6, 0, 12, 4}, {0, 4, 14, 6}, {14, 0, 18, 6}});
  AddPassage(after_graph, 0, 2, 6, 2.1);  // was 0-1: now between 0 and the merged 1
  AddPassage(after_graph, 0, 3, 3, 4);    // unchanged
  AddPassage(after_graph, 3, 4, 14, 5);   // new
  const proto::AreaGraph after = Next(after_graph, &before);
  ASSERT_EQ(AreaIds(after), (Ids{0, 4, 1, 3, 5}));

  const proto::AreaGraphDiff diff = DiffAreaGraphs(before, after);
  EXPECT_EQ(diff.from_version(), 1);
  EXPECT_EQ(diff.to_version(), 2);
  EXPECT_EQ(ToIds(diff.added_areas()), (Ids{4, 5}));
  EXPECT_EQ(ToIds(diff.added_from()), (Ids{0, -1}));
  EXPECT_EQ(ToIds(diff.removed_areas()), (Ids{2}));
  EXPECT_EQ(ToIds(diff.removed_into()), (Ids{1}));
  ASSERT_EQ(diff.changed_areas_size(), 3);
  const proto::AreaChange& split = diff.changed_areas(0);
  EXPECT_EQ(split.stable_id(), 0);
  EXPECT_EQ(ToIds(split.split_into()), (Ids{4}));
  EXPECT_TRUE(split.shrunk());
  EXPECT_NEAR(split.area_before_m2(), 24, 1e-9);
  EXPECT_NEAR(split.area_after_m2(), 16, 1e-9);
  const proto::AreaChange& merged = diff.changed_areas(1);
  EXPECT_EQ(merged.stable_id(), 1);
  EXPECT_EQ(ToIds(merged.merged_from()), (Ids{2}));
  EXPECT_TRUE(merged.grown());
  EXPECT_TRUE(merged.passages_changed());  // passage 1 (to area 2) is gone
  const proto::AreaChange& grown = diff.changed_areas(2);
  EXPECT_EQ(grown.stable_id(), 3);
  EXPECT_TRUE(grown.grown());
  EXPECT_FALSE(grown.shrunk());
  EXPECT_TRUE(grown.passages_changed());  // passage to area 5
  EXPECT_EQ(ToIds(diff.unchanged_areas()), Ids{});

  // Passage 0 joined areas 0 and 1 before and after (1 kept its id).
  EXPECT_EQ(ToIds(diff.unchanged_passages()), (Ids{0, 2}));
  EXPECT_EQ(ToIds(diff.removed_passages()), (Ids{1}));
  EXPECT_EQ(ToIds(diff.added_passages()), (Ids{3}));
  EXPECT_EQ(diff.changed_passages_size(), 0);

  const std::string text = FormatAreaGraphDiff(diff);
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "version 1 -> 2: areas 2 added, 1 removed, 3 changed, 0 unchanged; passages 1 added, "
            "1 removed, 0 changed, 2 unchanged");
  EXPECT_NE(text.find("  + area 4 (from area 0)\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  + area 5\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  - area 2 (into area 1)\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  ~ area 0: split off 4, shrunk (24.0 -> 16.0 m2)\n"), std::string::npos)
      << text;
  EXPECT_NE(text.find("  ~ area 1: took in 2, grown, passages changed"), std::string::npos) << text;
}

TEST(AreaGraphDiffTest, SmallChangesStayUnderTheThresholds) {
  proto::AreaGraph graph = RectGraph(Frame(200, 100), {{0, 0, 5, 4}, {5, 0, 9, 4}});
  AddPassage(graph, 0, 1, 5, 2);
  const proto::AreaGraph before = Next(graph, nullptr);
  proto::AreaGraph moved = RectGraph(Frame(200, 100), {{0, 0, 5.2, 4}, {5.2, 0, 9, 4}});
  AddPassage(moved, 0, 1, 5.2, 2.3);
  const proto::AreaGraph after = Next(moved, &before);
  proto::AreaGraphDiff diff = DiffAreaGraphs(before, after);
  EXPECT_EQ(ToIds(diff.unchanged_areas()), (Ids{0, 1}));
  EXPECT_EQ(ToIds(diff.unchanged_passages()), (Ids{0}));

  DiffThresholds strict;
  strict.size = 0.02;
  strict.passage_m = 0.2;
  diff = DiffAreaGraphs(before, after, strict);
  ASSERT_EQ(diff.changed_areas_size(), 2);
  EXPECT_TRUE(diff.changed_areas(0).grown());
  EXPECT_TRUE(diff.changed_areas(1).shrunk());
  ASSERT_EQ(diff.changed_passages_size(), 1);
  EXPECT_NEAR(diff.changed_passages(0).moved_m(), std::hypot(0.2, 0.3), 1e-9);
}

TEST(AreaGraphDiffTest, IdenticalVersionsHaveNothingToReport) {
  proto::AreaGraph graph = RectGraph(Frame(200, 100), {{0, 0, 5, 4}, {5, 0, 9, 4}});
  AddPassage(graph, 0, 1, 5, 2);
  const proto::AreaGraph first = Next(graph, nullptr);
  const proto::AreaGraphDiff diff = DiffAreaGraphs(first, Next(graph, &first));
  EXPECT_EQ(diff.added_areas_size() + diff.removed_areas_size() + diff.changed_areas_size(), 0);
  EXPECT_EQ(diff.unchanged_areas_size(), 2);
  EXPECT_EQ(diff.unchanged_passages_size(), 1);
}

TEST(AreaGraphDiffTest, RefusesGraphsWithoutStableIds) {
  const proto::AreaGraph graph = RectGraph(Frame(200, 100), {{0, 0, 5, 4}});
  const proto::AreaGraph matched = Next(graph, nullptr);
  EXPECT_THROW(DiffAreaGraphs(graph, matched), InputError);
  EXPECT_THROW(DiffAreaGraphs(matched, graph), InputError);
}

}  // namespace
}  // namespace areagraph::testing
