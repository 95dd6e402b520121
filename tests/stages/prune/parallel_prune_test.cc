// Voronoi's dual and prune's region look-ups and alpha shape run over ranges
// on OpenCV's pool (stages/geometry/parallel_ranges.h) on a map big enough
// to be split; their outputs must be those of one thread, byte for byte.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "stages/geometry/obstacle_sites.h"
#include "stages/geometry/site_alpha_shape.h"
#include "stages/geometry/site_triangulation.h"
#include "stages/prune/topology_graph_builder.h"
#include "stages/voronoi/voronoi_stage.h"
#include "tests/support/area_test_support.h"
#include "tests/support/thread_count.h"
#include "tools/example_maps/random_floor_plan.h"

namespace areagraph::testing {
namespace {

// run() with OpenCV's pool at `threads` threads; the count is restored
// afterwards, also when run() throws.
template <typename Run>
auto WithThreads(int threads, const Run& run) {
  const ThreadCount count(threads);
  return run();
}

// An office plan tiled n x n into one map (5 x 5: about 55 000 Voronoi
// vertices and more Delaunay faces, several ranges of each).
proto::CleanedMap TiledOffice(uint32_t seed, int n) {
  cv::Mat tiled;
  cv::repeat(floorplan::RandomOfficePlan(seed).image(), n, n, tiled);
  return CleanedMapFromImage(tiled);
}

struct StageOutputs {
  std::string voronoi;
  std::string prune_on_voronois;  // prune on the triangulation voronoi kept
  std::string prune_on_its_own;   // prune triangulating the sites again
  int vertices = 0;
};

StageOutputs RunStages(const proto::CleanedMap& map) {
  const proto::PipelineOptions options;
  StageOutputs out;
  const proto::VoronoiDiagram diagram = ComputeVoronoiStage(map, options.voronoi());
  out.vertices = diagram.vertex_x_size();
  out.voronoi = diagram.SerializeAsString();
  out.prune_on_voronois = BuildTopologyGraph(diagram, map, options.prune()).SerializeAsString();
  DropSiteTriangulation();
  out.prune_on_its_own = BuildTopologyGraph(diagram, map, options.prune()).SerializeAsString();
  return out;
}

TEST(ParallelPruneTest, VoronoiAndPruneOnTwoThreadsGiveOneThreadsBytes) {
  for (const uint32_t seed : {5u, 23u}) {
    const proto::CleanedMap map = TiledOffice(seed, 5);
    const StageOutputs one = WithThreads(1, [&] { return RunStages(map); });
    const StageOutputs two = WithThreads(2, [&] { return RunStages(map); });
    // Past two ranges of the dual's faces (16 384 each, and there are more
    // faces than vertices) and of the look-ups (4 096 points each).
    ASSERT_GT(one.vertices, 2 * 16384) << "seed " << seed << ": too small to be split";
    EXPECT_EQ(one.voronoi, two.voronoi) << "seed " << seed;
    EXPECT_EQ(one.prune_on_voronois, two.prune_on_voronois) << "seed " << seed;
    EXPECT_EQ(one.prune_on_its_own, two.prune_on_its_own) << "seed " << seed;
    EXPECT_EQ(one.prune_on_voronois, one.prune_on_its_own) << "seed " << seed;
  }
}

// The batch look-up gives each vertex the answer of EnclosedRegionAt called
// vertex by vertex, and leaves the walks' start where those calls leave it:
// plain walks afterwards (whose answer on an edge depends on it) agree.
TEST(ParallelPruneTest, BatchRegionLookUpsAreTheOneByOneCalls) {
  const proto::CleanedMap map = TiledOffice(11, 3);
  const proto::PipelineOptions options;
  const proto::VoronoiDiagram diagram = ComputeVoronoiStage(map, options.voronoi());
  DropSiteTriangulation();
  const PointList sites =
      ObstacleSites(map.cells(), map.frame().width_px(), map.frame().height_px());
  PointList positions;
  for (int v = 0; v < diagram.vertex_x_size(); ++v) {
    positions.emplace_back(diagram.vertex_x(v), diagram.vertex_y(v));
  }
  const double alpha_px = options.prune().boundary_alpha_radius_m() / map.frame().resolution_m();
  SiteAlphaShape batch(sites, alpha_px), single(sites, alpha_px);
  ASSERT_EQ(batch.NameVertexFaces(positions), static_cast<int>(positions.size()));
  ASSERT_EQ(single.NameVertexFaces(positions), static_cast<int>(positions.size()));
  ASSERT_EQ(batch.FindEnclosedRegions(), single.FindEnclosedRegions());
  // Every fifth point is a site instead: on a Delaunay vertex whose faces
  // lie in different regions, so its answer is the face where the plain walk
  // from the last one stops. Every third point is not asked for.
  PointList points = positions;
  for (size_t v = 2; v < points.size(); v += 5) points[v] = sites[v * 7919 % sites.size()];
  auto wanted = [](int v) { return v % 3 != 1; };
  const std::vector<int> regions =
      WithThreads(2, [&] { return batch.EnclosedRegionsAt(points, wanted); });
  ASSERT_EQ(regions.size(), points.size());
  int inside = 0;
  for (size_t v = 0; v < points.size(); ++v) {
    const int expected = wanted(v) ? single.EnclosedRegionAt(points[v], v) : -1;
    ASSERT_EQ(regions[v], expected) << "vertex " << v;
    inside += expected >= 0;
  }
  EXPECT_GT(inside, 1000);
  for (size_t v = 0; v < points.size(); v += 101) {
    ASSERT_EQ(batch.EnclosedRegionAt(points[v]), single.EnclosedRegionAt(points[v]))
        << "plain walk to vertex " << v;
  }
}

}  // namespace
}  // namespace areagraph::testing
