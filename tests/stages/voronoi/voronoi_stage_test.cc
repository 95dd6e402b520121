#include "stages/voronoi/voronoi_stage.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/error.h"
#include "stages/common/voronoi_arrays.h"
#include "stages/geometry/obstacle_sites.h"
#include "tests/support/test_grids.h"

namespace areagraph {
namespace {

using testing::TestGrid;

TEST(VoronoiStage, DiagramOfARoomUsesTheObstacleSites) {
  TestGrid grid(60, 40, proto::CELL_UNKNOWN);
  grid.Fill(5, 5, 54, 34, proto::CELL_FREE).Walls(5, 5, 54, 34, 2);
  const proto::CleanedMap map = grid.ToCleanedMap(0.1);
  const proto::VoronoiDiagram d = ComputeVoronoiStage(map, proto::VoronoiOptions());
  EXPECT_EQ(d.format_version(), 2u);
  EXPECT_FALSE(HasVoronoiMessages(d));  // format 2: arrays only
  EXPECT_EQ(d.frame().SerializeAsString(), map.frame().SerializeAsString());
  const std::vector<Eigen::Vector2d> sites = ObstacleSites(grid.cells(), 60, 40);
  ASSERT_EQ(d.site_x_size(), int(sites.size()));
  ASSERT_EQ(d.site_y_size(), int(sites.size()));
  for (int i = 0; i < d.site_x_size(); ++i) {
    EXPECT_EQ(d.site_x(i), sites[i].x());
    EXPECT_EQ(d.site_y(i), sites[i].y());
  }
  // The room's medial axis runs along y = 20, midway between the inner wall
  // rows (site centres y = 6.5 and 33.5), with vertices between site columns.
  double deepest = 0;
  double deepest_y = 0;
  ASSERT_EQ(d.vertex_clearance_px_size(), d.vertex_x_size());
  for (int v = 0; v < d.vertex_x_size(); ++v) {
    const double x = d.vertex_x(v), y = d.vertex_y(v);
    if (x < 7 || x > 53 || y < 7 || y > 33) continue;  // inside the room only
    if (d.vertex_clearance_px(v) > deepest) {
      deepest = d.vertex_clearance_px(v);
      deepest_y = y;
    }
  }
  EXPECT_NEAR(deepest, std::hypot(0.5, 13.5), 1e-9);
  EXPECT_NEAR(deepest_y, 20, 1e-9);
}

TEST(VoronoiStage, RejectsMapsWithoutFreeSpaceOrSites) {
  EXPECT_THROW(ComputeVoronoiStage(TestGrid(10, 10, proto::CELL_OCCUPIED).ToCleanedMap(),
                                   proto::VoronoiOptions()),
               InputError);
  try {
    ComputeVoronoiStage(TestGrid(10, 10).ToCleanedMap(), proto::VoronoiOptions());
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "the map has no obstacle cells next to free space");
  }
  TestGrid line(10, 10);
  line.Fill(2, 5, 8, 5, proto::CELL_OCCUPIED);  // sites all on one line
  EXPECT_THROW(ComputeVoronoiStage(line.ToCleanedMap(), proto::VoronoiOptions()), InputError);
  line.Fill(2, 6, 8, 6, proto::CELL_OCCUPIED);  // two rows: a proper diagram
  EXPECT_GT(ComputeVoronoiStage(line.ToCleanedMap(), proto::VoronoiOptions()).vertex_x_size(), 0);
  TestGrid dot(10, 10);
  dot.Fill(4, 4, 4, 4, proto::CELL_OCCUPIED);
  EXPECT_THROW(ComputeVoronoiStage(dot.ToCleanedMap(), proto::VoronoiOptions()), InputError);
}

}  // namespace
}  // namespace areagraph
