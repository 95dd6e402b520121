// ag-voronoi keeps its Delaunay triangulation for ag-prune in one process
// (stages/geometry/site_triangulation.h): prune takes it, and the Topology
// Graph is the same, byte for byte, as when prune triangulates the sites
// itself (as the ag-prune executable does).
#include <gtest/gtest.h>

#include "stages/clean/clean_stage.h"
#include "stages/geometry/obstacle_sites.h"
#include "stages/geometry/site_triangulation.h"
#include "stages/import/import_stage.h"
#include "stages/pipeline/map_pipeline.h"
#include "stages/prune/topology_graph_builder.h"
#include "stages/voronoi/voronoi_stage.h"
#include "tests/support/area_test_support.h"
#include "tests/support/test_support.h"
#include "tools/example_maps/random_floor_plan.h"

namespace areagraph::testing {
namespace {

TEST(VoronoiTriangulationTest, PruneOnVoronoisTriangulationGivesTheSameGraph) {
  for (const uint32_t seed : {3u, 11u}) {
    const proto::CleanedMap map = CleanedMapFromImage(floorplan::RandomOfficePlan(seed).image());
    const proto::PipelineOptions options;
    const PointList sites =
        ObstacleSites(map.cells(), map.frame().width_px(), map.frame().height_px());

    const proto::VoronoiDiagram diagram = ComputeVoronoiStage(map, options.voronoi());
    SiteTriangulationPtr kept = TakeSiteTriangulation(sites);
    ASSERT_NE(kept, nullptr) << "voronoi kept nothing for seed " << seed;
    KeepSiteTriangulation(std::move(kept), sites);
    const proto::TopologyGraph on_voronois = BuildTopologyGraph(diagram, map, options.prune());
    EXPECT_EQ(TakeSiteTriangulation(sites), nullptr) << "prune left it kept";

    const proto::TopologyGraph on_its_own = BuildTopologyGraph(diagram, map, options.prune());
    EXPECT_GT(on_its_own.edges_size(), 5);
    EXPECT_EQ(on_voronois.SerializeAsString(), on_its_own.SerializeAsString()) << "seed " << seed;
  }
}

TEST(VoronoiTriangulationTest, APipelineThatStopsAtVoronoiKeepsNothing) {
  const proto::PipelineOptions options;
  auto store = OpenArtifactStore(":memory:");
  const ImportSource source = ReadImportSource(SourcePath("examples/two_rooms.png"));
  RunCachedStage(*store, "m", StageOf(kImportStage), options, ImportInputs(source), [&] {
    return std::make_unique<proto::GridMap>(ImportGridMap(source, options.import()));
  });
  RunMapPipeline(*store, "m", options, false, PipelineObserver{}, kCleanStage, kVoronoiStage);
  const proto::CleanedMap cleaned =
      CleanGridMap(ImportGridMap(source, options.import()), options.clean());
  const PointList sites =
      ObstacleSites(cleaned.cells(), cleaned.frame().width_px(), cleaned.frame().height_px());
  EXPECT_EQ(TakeSiteTriangulation(sites), nullptr) << "kept past the pipeline's end";

  ComputeVoronoiStage(cleaned, options.voronoi());  // the stage alone keeps it
  EXPECT_NE(TakeSiteTriangulation(sites), nullptr);
}

}  // namespace
}  // namespace areagraph::testing
