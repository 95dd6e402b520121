// The id stability that tools/bench-live.sh and tools/bench-match-tuning.sh
// report: an area whose ground-truth room is fully seen in two updates keeps
// its id when the id is still on the area that holds the most of what the
// area had of that room. Constructed graphs of vertical strips over two rooms.
#include "tools/bench/id_stability.h"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

namespace areagraph {
namespace {

constexpr int kWidth = 200, kHeight = 60;  // 10 m x 3 m at 0.05 m

// Room 1 is x < 6 m, room 2 the rest; all seen.
cv::Mat Rooms() {
  cv::Mat rooms(kHeight, kWidth, CV_32S, cv::Scalar(2));
  rooms.colRange(0, 120).setTo(1);
  return rooms;
}

cv::Mat AllSeen() { return cv::Mat(kHeight, kWidth, CV_8U, cv::Scalar(255)); }

// A matched graph of full-height strips: (stable id, x0, x1) in metres.
proto::AreaGraph Strips(const std::vector<std::tuple<int, double, double>>& strips) {
  proto::AreaGraph graph;
  proto::MapFrame* frame = graph.mutable_frame();
  frame->set_resolution_m(0.05);
  frame->set_width_px(kWidth);
  frame->set_height_px(kHeight);
  graph.mutable_version()->set_number(1);
  for (const auto& [id, x0, x1] : strips) {
    proto::Area* area = graph.add_areas();
    area->set_id(graph.areas_size() - 1);
    area->set_stable_id(id);
    for (const auto& [x, y] :
         std::vector<std::pair<double, double>>{{x0, 0}, {x1, 0}, {x1, 3}, {x0, 3}}) {
      proto::Point2* p = area->mutable_polygon_m()->mutable_outer()->add_points();
      p->set_x(x);
      p->set_y(y);
    }
  }
  return graph;
}

IdStability Compare(const proto::AreaGraph& before, const proto::AreaGraph& after) {
  const cv::Mat rooms = Rooms(), seen = AllSeen();
  return CompareViews(ViewAgainstGroundTruth(before, rooms, seen),
                      ViewAgainstGroundTruth(after, rooms, seen));
}

TEST(IdStabilityTest, AnAreaThatNoiseTipsUnderHalfInItsRoomKeepsItsId) {
  // Area 5 has 52 % of its cells in room 1, then (its border moved by 0.2 m)
  // 48 %: the same area, same id. The earlier test counted it lost.
  const IdStability stability = Compare(Strips({{4, 0, 3.4}, {5, 3.4, 8.4}, {6, 8.4, 10}}),
                                        Strips({{4, 0, 3.6}, {5, 3.6, 8.6}, {6, 8.6, 10}}));
  EXPECT_EQ(stability.tracked, 3);  // 4 and 5 in room 1, 6 in room 2
  EXPECT_EQ(stability.kept, 3);
  EXPECT_EQ(stability.kept_same_room, 2);
  EXPECT_TRUE(stability.lost.empty());
}

TEST(IdStabilityTest, AnIdThatMovedOffItsPlaceIsLost) {
  // Area 7 was all of room 1; now id 7 is on its first metre only, and a new
  // area 9 has the rest: 7 is still in room 1 but holds a sixth of it.
  const IdStability stability =
      Compare(Strips({{7, 0, 6}, {8, 6, 10}}), Strips({{7, 0, 1}, {9, 1, 6}, {8, 6, 10}}));
  EXPECT_EQ(stability.tracked, 2);
  EXPECT_EQ(stability.kept, 1);
  EXPECT_EQ(stability.kept_same_room, 2);  // the earlier test did not see it
  EXPECT_EQ(stability.lost, std::set<int>{7});
}

TEST(IdStabilityTest, ASplitKeepsTheIdOnItsLargestPart) {
  // Area 7 (all of room 1) split in three: 2.4, 1.8 and 1.8 m. The id on the
  // largest part is kept (though it holds only 40 %); on a smaller part it is not.
  EXPECT_EQ(Compare(Strips({{7, 0, 6}, {8, 6, 10}}),
                    Strips({{7, 0, 2.4}, {9, 2.4, 4.2}, {10, 4.2, 6}, {8, 6, 10}}))
                .kept,
            2);
  EXPECT_EQ(Compare(Strips({{7, 0, 6}, {8, 6, 10}}),
                    Strips({{9, 0, 2.4}, {7, 2.4, 4.2}, {10, 4.2, 6}, {8, 6, 10}}))
                .lost,
            std::set<int>{7});
}

TEST(IdStabilityTest, AJoinLosesTheSwallowedIdOnly) {
  // Areas 1 [0,4] and 2 [4,6] of room 1 joined into one area with id 1.
  const IdStability stability =
      Compare(Strips({{1, 0, 4}, {2, 4, 6}, {3, 6, 10}}), Strips({{1, 0, 6}, {3, 6, 10}}));
  EXPECT_EQ(stability.tracked, 3);
  EXPECT_EQ(stability.kept, 2);
  EXPECT_EQ(stability.lost, std::set<int>{2});
  EXPECT_EQ(stability.ids_before, 3);
  EXPECT_EQ(stability.ids_kept, 2);
}

TEST(IdStabilityTest, RoomsNotFullySeenAreNotTracked) {
  cv::Mat seen = AllSeen();
  seen.colRange(150, 200).setTo(0);  // room 2 is 80 px wide: 62 % seen
  const cv::Mat rooms = Rooms();
  const proto::AreaGraph graph = Strips({{1, 0, 6}, {2, 6, 10}});
  const IdStability stability = CompareViews(ViewAgainstGroundTruth(graph, rooms, seen),
                                             ViewAgainstGroundTruth(graph, rooms, AllSeen()));
  EXPECT_EQ(stability.tracked, 1);
  EXPECT_EQ(stability.kept, 1);
}

TEST(IdStabilityTest, SumsAdd) {
  IdStability total;
  IdStability step;
  step.tracked = 3;
  step.kept = 2;
  step.kept_same_room = 1;
  step.ids_before = 4;
  step.ids_kept = 3;
  total += step;
  total += step;
  EXPECT_EQ(total.tracked, 6);
  EXPECT_EQ(total.kept, 4);
  EXPECT_EQ(total.kept_same_room, 2);
  EXPECT_EQ(total.ids_before, 8);
  EXPECT_EQ(total.ids_kept, 6);
}

}  // namespace
}  // namespace areagraph
