// MarkClosedPassages: a cut on a line of closing sites is marked, a cut
// away from it is not.
#include "stages/cut/closed_passages.h"

#include <gtest/gtest.h>

namespace areagraph::testing {
namespace {

constexpr double kResolutionM = 0.05;

proto::CutGraph TwoPassages() {
  proto::CutGraph graph;
  for (const auto& [x, y] : {std::pair{40.0, 20.0}, std::pair{40.0, 60.0}}) {
    proto::PassagePoint* passage = graph.add_passage_points();
    passage->set_id(graph.passage_points_size() - 1);
    passage->mutable_position()->set_x(x);
    passage->mutable_position()->set_y(y);
  }
  return graph;
}

// Sites one per pixel along x = 41.5, y in [5, 35]: a closed door 1.5 px
// beside the first passage and 25 px from the second.
PointList DoorLine() {
  PointList sites;
  for (int y = 5; y <= 35; ++y) sites.emplace_back(41.5, y);
  return sites;
}

TEST(ClosedPassagesTest, OnlyTheCutOnTheClosedLineIsMarked) {
  proto::CutGraph graph = TwoPassages();
  MarkClosedPassages(ClosedLines(DoorLine(), kResolutionM), &graph);
  EXPECT_TRUE(graph.passage_points(0).closed_by_cut());
  EXPECT_FALSE(graph.passage_points(1).closed_by_cut());
}

TEST(ClosedPassagesTest, ACutJustBeyondTheReachIsNotMarked) {
  proto::CutGraph graph = TwoPassages();
  PointList sites;
  // 0.15 m is 3 px: a line 3.5 px away is out of reach.
  for (int y = 5; y <= 35; ++y) sites.emplace_back(43.5, y);
  MarkClosedPassages(ClosedLines(sites, kResolutionM), &graph);
  EXPECT_FALSE(graph.passage_points(0).closed_by_cut());
}

TEST(ClosedPassagesTest, NoClosingSitesMarkNothing) {
  proto::CutGraph graph = TwoPassages();
  MarkClosedPassages(ClosedLines({}, kResolutionM), &graph);
  EXPECT_FALSE(graph.passage_points(0).closed_by_cut());
  EXPECT_FALSE(graph.passage_points(1).closed_by_cut());
}

}  // namespace
}  // namespace areagraph::testing
