// The simulated exploration of tools/bench-live.sh: maps that grow along the
// robot's path, noise that differs from map to map, crops that follow what
// was seen, and the large generated floor with its ground truth.
#include "tools/example_maps/exploration.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "tools/example_maps/floor_plan.h"
#include "tools/example_maps/random_floor_plan.h"

namespace areagraph {
namespace {

using namespace floorplan;

// Three rooms off a corridor, and a fourth room that no door leads to.
cv::Mat Truth() {
  FloorPlan plan(24, 12);
  DrawRoom(plan, {1, 6, 16, 2});
  for (int k = 0; k < 3; ++k) {
    DrawRoom(plan, {1 + 5.0 * k, 1, 5, 5});
    DrawDoor(plan, 3.5 + 5.0 * k, 6, 0.9, WallDirection::kHorizontal);
  }
  DrawRoom(plan, {18, 1, 5, 8});
  return ClassifyGrey(plan.image());
}

int SeenFree(const cv::Mat& truth, const ExplorationMap& map) {
  return cv::countNonZero(map.seen & (truth == kFreeCell));
}

TEST(ExplorationTest, MapsGrowAlongThePathUntilEveryRegionIsSeen) {
  const cv::Mat truth = Truth();
  ExplorationSettings settings;
  settings.steps = 5;
  Exploration exploration(truth, settings);
  EXPECT_GT(exploration.scans(), 5);
  int before = 0;
  for (int step = 1; step <= 5; ++step) {
    const ExplorationMap map = exploration.MapAfter(step, step);
    const int seen = SeenFree(truth, map);
    EXPECT_GE(seen, before) << step;
    before = seen;
    // Only what was seen is known; the crop holds all of it.
    EXPECT_EQ(cv::countNonZero(map.seen(map.crop)), cv::countNonZero(map.seen));
    EXPECT_EQ(map.cells.size(), map.crop.size());
  }
  // Everything free is seen in the end, the closed room included.
  EXPECT_EQ(before, cv::countNonZero(truth == kFreeCell));
  EXPECT_LT(SeenFree(truth, Exploration(truth, settings).MapAfter(1, 1)), before);
}

TEST(ExplorationTest, NoiseDiffersFromMapToMapButNotFromRunToRun) {
  const cv::Mat truth = Truth();
  ExplorationSettings settings;
  settings.steps = 1;
  Exploration exploration(truth, settings);
  const ExplorationMap first = exploration.MapAfter(1, 7);
  const ExplorationMap again = exploration.MapAgain(8);
  ASSERT_EQ(first.crop, again.crop);
  const int changed = cv::countNonZero(first.cells != again.cells);
  EXPECT_GT(changed, 0);
  // A few cells along the walls and some speckles: a small part of the map.
  EXPECT_LT(changed, 0.02 * first.cells.total());
  EXPECT_EQ(cv::countNonZero(exploration.MapAgain(7).cells != first.cells), 0);

  ExplorationSettings quiet = settings;
  quiet.wall_noise = quiet.frontier_noise = quiet.speckles_per_m2 = 0;
  Exploration clean(truth, quiet);
  const ExplorationMap map = clean.MapAfter(1, 1);
  cv::Mat known = truth(map.crop).clone();
  known.setTo(kUnknownCell, map.seen(map.crop) == 0);
  EXPECT_EQ(cv::countNonZero(map.cells != known), 0);
}

TEST(ExplorationTest, TheLargeFloorComesWithItsRooms) {
  FloorPlan closed(1, 1);
  const FloorPlan plan = LargeOfficePlan(40, 30, 3, &closed);
  EXPECT_EQ(plan.image().size(), closed.image().size());
  cv::Mat rooms;
  const int regions = cv::connectedComponents(closed.image() == kFreeGrey, rooms, 4) - 1;
  // Two branches of 12 m fit in 30 m: the spine, two branches, and rooms
  // 3 to 7 m wide along 37 m on four sides.
  EXPECT_GE(regions, 3 + 4 * 5);
  EXPECT_LE(regions, 3 + 4 * 12);
  // With the doors, everything but furniture and noise dots is one region.
  cv::Mat joined;
  cv::Mat stats, centroids;
  const int parts =
      cv::connectedComponentsWithStats(plan.image() == kFreeGrey, joined, stats, centroids, 4);
  int big = 0;
  for (int i = 1; i < parts; ++i) big += stats.at<int>(i, cv::CC_STAT_AREA) > 400;
  EXPECT_EQ(big, 1);
}

}  // namespace
}  // namespace areagraph
