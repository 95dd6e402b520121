// ag-voronoi keeps its Delaunay triangulation for ag-prune in one process
// (stages/geometry/site_triangulation.h): prune takes it, and the Topology
// Graph is the same, byte for byte, as when prune triangulates the sites
// itself (as the ag-prune executable does).
#include <gtest/gtest.h>

#include "stages/clean/clean_stage.h"
#include "stages/geometry/obstacle_sites.h"
#include "stages/geometry/site_alpha_shape.h"
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

// A random office plan through voronoi, with the triangulation it kept.
struct VoronoiRun {
  proto::CleanedMap map;
  PointList sites;
  proto::VoronoiDiagram diagram;
  SiteTriangulationPtr kept;

  explicit VoronoiRun(uint32_t seed)
      : map(CleanedMapFromImage(floorplan::RandomOfficePlan(seed).image())),
        sites(ObstacleSites(map.cells(), map.frame().width_px(), map.frame().height_px())),
        diagram(ComputeVoronoiStage(map, proto::VoronoiOptions())),
        kept(TakeSiteTriangulation(sites)) {}
};

TEST(VoronoiTriangulationTest, PruneOnVoronoisTriangulationGivesTheSameGraph) {
  for (const uint32_t seed : {3u, 11u}) {
    VoronoiRun run(seed);
    const proto::PipelineOptions options;
    const proto::CleanedMap& map = run.map;
    const PointList& sites = run.sites;
    const proto::VoronoiDiagram& diagram = run.diagram;
    ASSERT_NE(run.kept, nullptr) << "voronoi kept nothing for seed " << seed;
    KeepSiteTriangulation(std::move(run.kept), sites);
    const proto::TopologyGraph on_voronois = BuildTopologyGraph(diagram, map, options.prune());
    EXPECT_EQ(TakeSiteTriangulation(sites), nullptr) << "prune left it kept";

    const proto::TopologyGraph on_its_own = BuildTopologyGraph(diagram, map, options.prune());
    EXPECT_GT(on_its_own.edges_size(), 5);
    EXPECT_EQ(on_voronois.SerializeAsString(), on_its_own.SerializeAsString()) << "seed " << seed;
  }
}

// Prune asks for the region of each Voronoi vertex starting at the vertex's
// own Delaunay face (which voronoi leaves named in its triangulation); for
// points on an edge the plain walk's face depends on where the last walk
// ended, so every answer, and every plain walk after them, must be the plain
// walks' from one vertex to the next.
TEST(VoronoiTriangulationTest, RegionsByVoronoiVertexAreThePlainWalksOnes) {
  for (const uint32_t seed : {3u, 11u, 19u}) {
    VoronoiRun run(seed);
    const proto::PipelineOptions options;
    const proto::VoronoiDiagram& diagram = run.diagram;
    ASSERT_NE(run.kept, nullptr);
    const double alpha_px =
        options.prune().boundary_alpha_radius_m() / run.map.frame().resolution_m();
    SiteAlphaShape by_vertex(std::move(run.kept), alpha_px);
    SiteAlphaShape plain(run.sites, alpha_px);
    ASSERT_EQ(by_vertex.FindEnclosedRegions(), plain.FindEnclosedRegions());
    // Grid maps' vertices lie on Delaunay edges often (the centre of a
    // square of sites is on its diagonal), so the put-off walks run.
    int inside = 0;
    for (int v = 0; v < diagram.vertex_x_size(); ++v) {
      const Eigen::Vector2d p(diagram.vertex_x(v), diagram.vertex_y(v));
      const int region = plain.EnclosedRegionAt(p);
      ASSERT_EQ(by_vertex.EnclosedRegionAt(p, v), region) << "seed " << seed << " vertex " << v;
      inside += region >= 0;
      if (v % 97 == 0) {  // a plain walk now and then must start where the plain ones ended
        const Eigen::Vector2d q(diagram.vertex_x(v / 2), diagram.vertex_y(v / 2));
        ASSERT_EQ(by_vertex.EnclosedRegionAt(q), plain.EnclosedRegionAt(q)) << "vertex " << v;
      }
    }
    EXPECT_GT(inside, 100) << "seed " << seed;
  }
}

// A triangulation made in prune (the diagram came from the store) names its
// vertices' faces by their circumcentres: every vertex is named, and the
// answers stay the plain walks'.
TEST(VoronoiTriangulationTest, VertexFacesNamedByCircumcentreGiveThePlainWalksAnswers) {
  for (const uint32_t seed : {3u, 19u}) {
    VoronoiRun run(seed);
    const proto::PipelineOptions options;
    const proto::VoronoiDiagram& diagram = run.diagram;
    const double alpha_px =
        options.prune().boundary_alpha_radius_m() / run.map.frame().resolution_m();
    PointList positions;
    for (int v = 0; v < diagram.vertex_x_size(); ++v) {
      positions.emplace_back(diagram.vertex_x(v), diagram.vertex_y(v));
    }
    ASSERT_NE(run.kept, nullptr);
    SiteAlphaShape on_voronois(std::move(run.kept), alpha_px);
    EXPECT_EQ(on_voronois.NameVertexFaces(positions), 0) << "voronoi's faces are named already";
    SiteAlphaShape named(run.sites, alpha_px);
    ASSERT_EQ(named.NameVertexFaces(positions), diagram.vertex_x_size()) << "seed " << seed;
    EXPECT_EQ(named.NameVertexFaces(positions), 0) << "named twice";
    SiteAlphaShape plain(run.sites, alpha_px);
    ASSERT_EQ(named.FindEnclosedRegions(), plain.FindEnclosedRegions());
    int inside = 0;
    for (int v = 0; v < diagram.vertex_x_size(); ++v) {
      const int region = plain.EnclosedRegionAt(positions[v]);
      ASSERT_EQ(named.EnclosedRegionAt(positions[v], v), region) << "seed " << seed << " v " << v;
      inside += region >= 0;
    }
    EXPECT_GT(inside, 100) << "seed " << seed;
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
