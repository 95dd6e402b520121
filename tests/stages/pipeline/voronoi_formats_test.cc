// The Voronoi diagram's two formats (stage_info.h: VoronoiDiagram 1 with a
// message per site, vertex and edge; 2 with packed arrays): prune reads an
// artifact of format 1, as stores from before voronoi 3 hold, into the same
// Topology Graph, byte for byte.
#include <gtest/gtest.h>

#include "common/error.h"
#include "stages/common/voronoi_arrays.h"
#include "stages/prune/topology_graph_builder.h"
#include "tests/support/area_test_support.h"
#include "tests/support/voronoi_messages.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using floorplan::DrawRoom;
using floorplan::FloorPlan;

TEST(VoronoiFormatsTest, PruneReadsFormatOneIntoTheSameGraph) {
  FloorPlan plan(12, 6);
  DrawRoom(plan, {0.5, 0.5, 6, 5.5});
  DrawRoom(plan, {6, 0.5, 11.5, 5.5});
  const proto::CleanedMap map = CleanedMapFromImage(plan.image());
  const AreaStages stages = RunAreaStages(map);
  ASSERT_FALSE(HasVoronoiMessages(stages.diagram));
  ASSERT_GT(VoronoiEdgeCount(stages.diagram), 100);

  const proto::VoronoiDiagram old_format = VoronoiAsMessages(stages.diagram);
  ASSERT_TRUE(HasVoronoiMessages(old_format));
  EXPECT_EQ(VoronoiEdgeCount(old_format), VoronoiEdgeCount(stages.diagram));
  const proto::TopologyGraph from_old = BuildTopologyGraph(old_format, map, stages.options.prune());
  EXPECT_GT(from_old.edges_size(), 0);
  EXPECT_EQ(from_old.SerializeAsString(), stages.topology.SerializeAsString());
}

TEST(VoronoiFormatsTest, FormatOneConvertsToTheSameArrays) {
  FloorPlan plan(6, 5);
  DrawRoom(plan, {0.5, 0.5, 5, 4});
  const proto::VoronoiDiagram diagram = RunAreaStages(CleanedMapFromImage(plan.image())).diagram;
  proto::VoronoiDiagram converted;
  EXPECT_EQ(&PackedVoronoi(diagram, &converted), &diagram) << "format 2 is read in place";
  proto::VoronoiDiagram from_old = PackedVoronoi(VoronoiAsMessages(diagram), &converted);
  EXPECT_EQ(from_old.format_version(), 1u);
  from_old.set_format_version(diagram.format_version());
  EXPECT_EQ(from_old.SerializeAsString(), diagram.SerializeAsString());
}

TEST(VoronoiFormatsTest, ArraysOfDifferentLengthsAreCorrupt) {
  FloorPlan plan(6, 5);
  DrawRoom(plan, {0.5, 0.5, 5, 4});
  const proto::VoronoiDiagram diagram = RunAreaStages(CleanedMapFromImage(plan.image())).diagram;
  proto::VoronoiDiagram converted;
  for (auto damage : std::vector<void (*)(proto::VoronoiDiagram*)>{
           [](proto::VoronoiDiagram* d) { d->mutable_site_y()->RemoveLast(); },
           [](proto::VoronoiDiagram* d) { d->add_vertex_clearance_px(1); },
           [](proto::VoronoiDiagram* d) { d->mutable_edge_left_site()->RemoveLast(); },
           [](proto::VoronoiDiagram* d) { d->add_ray_direction_x(0); }}) {
    proto::VoronoiDiagram damaged = diagram;
    damage(&damaged);
    EXPECT_THROW(PackedVoronoi(damaged, &converted), InputError);
  }
  EXPECT_NO_THROW(PackedVoronoi(diagram, &converted));
}

}  // namespace
}  // namespace areagraph::testing
