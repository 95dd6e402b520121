// ag-prune writes each edge's half and whole polygons from its chain's
// lists; they must be what UpdateEdgePolygons makes of the edge's path and
// sites as written.
#include <gtest/gtest.h>

#include "stages/geometry/edge_polygon.h"
#include "stages/prune/topology_graph_builder.h"
#include "stages/voronoi/voronoi_stage.h"
#include "tests/support/area_test_support.h"
#include "tools/example_maps/random_floor_plan.h"

namespace areagraph::testing {
namespace {

TEST(PrunePolygonsTest, EveryEdgesPolygonsAreThoseOfItsPathAndSites) {
  int edges = 0;
  for (const uint32_t seed : {2u, 5u, 9u}) {
    const proto::CleanedMap map = CleanedMapFromImage(floorplan::RandomOfficePlan(seed).image());
    const proto::VoronoiDiagram diagram = ComputeVoronoiStage(map, proto::VoronoiOptions());
    const proto::TopologyGraph graph =
        BuildTopologyGraph(diagram, map, proto::PipelineOptions().prune());
    for (const proto::GraphEdge& edge : graph.edges()) {
      proto::GraphEdge expected = edge;
      expected.clear_left_half();
      expected.clear_right_half();
      expected.clear_polygon();
      UpdateEdgePolygons(&expected);
      EXPECT_EQ(edge.SerializeAsString(), expected.SerializeAsString())
          << "seed " << seed << ", edge " << edge.id();
      ++edges;
    }
  }
  EXPECT_GT(edges, 30);
}

}  // namespace
}  // namespace areagraph::testing
