// Clean and Voronoi on real maps of ../shared/data (skipped without it).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "stages/clean/clean_stage.h"
#include "stages/import/import_stage.h"
#include "stages/voronoi/voronoi_stage.h"
#include "tests/support/test_support.h"
#include "tests/support/voronoi_messages.h"

namespace areagraph {
namespace {

class SharedMaps : public ::testing::TestWithParam<const char*> {};

TEST_P(SharedMaps, CleanAndVoronoiGiveSaneResults) {
  if (!testing::HaveSharedData()) GTEST_SKIP() << "no ../shared/data";
  const std::string path = testing::SharedDataPath(std::string("areagraph/input/") + GetParam());
  const proto::GridMap map = ImportGridMap(ReadImportSource(path), proto::ImportOptions());
  const std::string& before = map.cells();
  const long obstacles =
      long(before.size()) - std::count(before.begin(), before.end(), char(proto::CELL_FREE));

  const proto::CleanedMap cleaned = CleanGridMap(map, proto::CleanOptions());
  const std::string& after = cleaned.cells();
  ASSERT_EQ(after.size(), before.size());
  std::vector<int> removed(cleaned.removed_outlier_cells().begin(),
                           cleaned.removed_outlier_cells().end());
  removed.insert(removed.end(), cleaned.removed_furniture_cells().begin(),
                 cleaned.removed_furniture_cells().end());
  std::sort(removed.begin(), removed.end());
  EXPECT_TRUE(std::adjacent_find(removed.begin(), removed.end()) == removed.end());
  // Removed cells were obstacles (occupied, or unknown islands) and are free
  // now; nothing else changed.
  size_t next = 0;
  for (size_t i = 0; i < before.size(); ++i) {
    if (next < removed.size() && removed[next] == int(i)) {
      EXPECT_NE(before[i], char(proto::CELL_FREE));
      EXPECT_EQ(after[i], char(proto::CELL_FREE));
      ++next;
    } else if (before[i] != after[i]) {
      ADD_FAILURE() << "cell " << i << " changed without being recorded";
      break;
    }
  }
  EXPECT_LT(double(removed.size()), 0.2 * obstacles) << "removed " << removed.size();

  const proto::VoronoiDiagram d =
      VoronoiAsMessages(ComputeVoronoiStage(cleaned, proto::VoronoiOptions()));
  EXPECT_GT(d.sites_size(), 1000);
  EXPECT_GT(d.vertices_size(), d.sites_size() / 4);
  EXPECT_GT(d.edges_size(), d.vertices_size());
  for (const proto::VoronoiEdge& e : d.edges()) {
    ASSERT_TRUE(e.source() >= 0 && e.source() < d.vertices_size());
    ASSERT_TRUE(e.target() >= -1 && e.target() < d.vertices_size());
    ASSERT_TRUE(e.left_site() >= 0 && e.left_site() < d.sites_size());
    ASSERT_TRUE(e.right_site() >= 0 && e.right_site() < d.sites_size());
    ASSERT_NE(e.left_site(), e.right_site());
    ASSERT_GE(e.clearance_px(), 0.5 - 1e-9);  // distinct cell centres are >= 1 apart
  }
  // Deep vertices in free space (rooms and corridors), and their clearance
  // is the distance to the nearest site (checked on a sample).
  const int width = d.frame().width_px();
  int deep_free = 0;
  for (int v = 0; v < d.vertices_size(); ++v) {
    const proto::VoronoiVertex& vertex = d.vertices(v);
    const double x = vertex.position().x(), y = vertex.position().y();
    if (x < 0 || y < 0 || x >= width || y >= d.frame().height_px()) continue;
    if (after[int(y) * width + int(x)] != char(proto::CELL_FREE)) continue;
    if (vertex.clearance_px() >= 10) ++deep_free;
    if (v % 97 != 0) continue;
    double nearest = std::numeric_limits<double>::infinity();
    for (const proto::Point2& s : d.sites())
      nearest = std::min(nearest, std::hypot(s.x() - x, s.y() - y));
    EXPECT_NEAR(vertex.clearance_px(), nearest, 1e-6);
  }
  EXPECT_GT(deep_free, 20);
}

INSTANTIATE_TEST_SUITE_P(AreaGraphInputs, SharedMaps,
                         ::testing::Values("lab_a.png", "freiburg_building52.png",
                                           "Freiburg79_scan_furnitures_trashbins.png", "sistD.png"),
                         [](const auto& info) {
                           const std::string name = info.param;
                           return name.substr(0, name.find('.'));
                         });

}  // namespace
}  // namespace areagraph
