// Merge's compute splits rows and areas over OpenCV's pool: on one thread
// and on two it must give the same bytes.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <string>

#include "proto/pipeline_options.pb.h"
#include "stages/merge/area_graph_builder.h"
#include "tests/support/area_test_support.h"
#include "tests/support/thread_count.h"
#include "tools/example_maps/random_floor_plan.h"

namespace areagraph::testing {
namespace {

struct MergeResult {
  std::string graph;
  cv::Mat labels;
};

// With `keep_raster` false the labels go while the rooms' shapes may still
// be measured on the pool (BuildAreaGraph without a raster for the caller).
MergeResult MergeOn(int threads, const AreaStages& stages, const proto::CleanedMap& map,
                    bool keep_raster = true) {
  ThreadCount count(threads);
  MergeResult result;
  AreaRaster raster;
  proto::AreaGraph graph =
      BuildAreaGraph(stages.cut, map, stages.options.merge(), keep_raster ? &raster : nullptr);
  EXPECT_TRUE(graph.SerializeToString(&result.graph));
  result.labels = raster.labels;
  return result;
}

TEST(ParallelMergeTest, OneThreadAndTwoGiveTheSameAreaGraph) {
  // 60 x 40 m at 0.05 m/px: 1200 x 800 cells, rows and room boxes enough for
  // several ranges of every split (at least 2^16 cells a range).
  const floorplan::FloorPlan plan = floorplan::LargeOfficePlan(60, 40, /*seed=*/5);
  const proto::CleanedMap map = CleanedMapFromImage(plan.image());
  ASSERT_GE(map.frame().width_px() * map.frame().height_px(), 1 << 19);
  const AreaStages stages = RunAreaStages(map);
  const MergeResult one = MergeOn(1, stages, map);
  const MergeResult two = MergeOn(2, stages, map);
  ASSERT_GT(stages.areas.areas_size(), 20);
  EXPECT_EQ(one.graph, two.graph);
  ASSERT_EQ(one.labels.size(), two.labels.size());
  EXPECT_EQ(cv::countNonZero(one.labels != two.labels), 0);
  // And both are what the stages gave with the default thread count.
  std::string default_graph;
  ASSERT_TRUE(stages.areas.SerializeToString(&default_graph));
  EXPECT_EQ(one.graph, default_graph);
  EXPECT_EQ(MergeOn(2, stages, map, /*keep_raster=*/false).graph, default_graph);
  EXPECT_EQ(MergeOn(1, stages, map, /*keep_raster=*/false).graph, default_graph);
}

}  // namespace
}  // namespace areagraph::testing
