// BuildCutGraph on OpenCV's pool (its site tasks, pieces beside outlines, the
// sites' spatial sort): the Cut Graph is the same byte for byte on one thread and
// on two, whether the caller keeps the Topology Graph or gives it up.
#include <gtest/gtest.h>

#include <string>

#include "stages/cut/cut_graph_builder.h"
#include "stages/prune/topology_graph_builder.h"
#include "stages/voronoi/voronoi_stage.h"
#include "tests/support/area_test_support.h"
#include "tests/support/thread_count.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph {
namespace {

using testing::ThreadCount;

// A floor of 6 x 5 rooms, 4 m square, with doors to their neighbours, a desk
// standing free in every other room (islands) and sensor noise: over 8 192
// sites (the sort's tasks) and over 64 edges (two or more wall gap ranges).
floorplan::FloorPlan OfficeFloor() {
  constexpr int kCols = 6, kRows = 5;
  floorplan::FloorPlan plan(kCols * 4.0 + 1, kRows * 4.0 + 1);
  for (int r = 0; r < kRows; ++r) {
    for (int c = 0; c < kCols; ++c) floorplan::DrawRoom(plan, {0.5 + 4 * c, 0.5 + 4 * r, 4, 4});
  }
  for (int r = 0; r < kRows; ++r) {
    for (int c = 0; c < kCols; ++c) {
      const double x = 0.5 + 4 * c, y = 0.5 + 4 * r;
      if (c + 1 < kCols) {
        floorplan::DrawDoor(plan, x + 4, y + 1 + (r + c) % 3, 0.9,
                            floorplan::WallDirection::kVertical);
      }
      if (r + 1 < kRows && (r + c) % 2 == 0) {
        floorplan::DrawDoor(plan, x + 2, y + 4, 1.0, floorplan::WallDirection::kHorizontal);
      }
      if ((r * kCols + c) % 2 == 1) floorplan::DrawFurniture(plan, {x + 1.2, y + 1.4, 1.4, 0.9});
    }
  }
  floorplan::DrawNoiseDots(plan, 60, 11);
  return plan;
}

std::string CutBytes(const proto::TopologyGraph& topology, const proto::CleanedMap& map,
                     const proto::CutOptions& options, bool give_up) {
  proto::TopologyGraph owned = topology;
  const proto::CutGraph cut =
      give_up ? BuildCutGraph(owned, map, options, &owned) : BuildCutGraph(topology, map, options);
  EXPECT_GT(cut.room_shapes_size(), 10);
  EXPECT_GT(cut.passage_points_size(), 10);
  return cut.SerializeAsString();
}

TEST(CutThreadsTest, OneAndTwoThreadsGiveTheSameCutGraph) {
  const proto::CleanedMap map = testing::CleanDrawnMap(OfficeFloor().image());
  const proto::PipelineOptions options;
  const proto::TopologyGraph topology =
      BuildTopologyGraph(ComputeVoronoiStage(map, options.voronoi()), map, options.prune());
  ASSERT_GT(topology.edges_size(), 64);
  for (const bool give_up : {false, true}) {
    std::string one, two;
    {
      const ThreadCount threads(1);
      one = CutBytes(topology, map, options.cut(), give_up);
    }
    {
      const ThreadCount threads(2);
      two = CutBytes(topology, map, options.cut(), give_up);
    }
    EXPECT_TRUE(one == two) << (give_up ? "graph given up" : "graph kept");
    EXPECT_FALSE(one.empty());
  }
}

}  // namespace
}  // namespace areagraph
