// The Area Graph dataset's input maps (../shared/data, not in the repo) all
// import with plausible cell counts. Skipped when the data is absent.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "stages/common/grid_cells.h"
#include "stages/import/grid_map_decoder.h"
#include "tests/stages/import/import_test_util.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::HaveSharedData;
using testing::RunTool;
using testing::SharedDataPath;
using testing::TempDir;

struct SharedMap {
  std::string name;
  int width;
  int height;
};

// Sizes from shared/data/areagraph/README.md.
const std::vector<SharedMap> kMaps = {
    {"Freiburg101_scan", 1344, 800},
    {"Freiburg101_scan_furnitures_trashbins", 1344, 800},
    {"Freiburg79_scan_furnitures_trashbins", 800, 544},
    {"freiburg_building101", 281, 542},
    {"freiburg_building52", 543, 292},
    {"freiburg_building79", 700, 289},
    {"intel_map", 586, 587},
    {"lab_a", 645, 573},
    {"lab_b", 1237, 672},
    {"lab_c", 541, 433},
    {"lab_c_scan_furnitures_trashbins", 800, 544},
    {"lab_d", 920, 581},
    {"lab_d_scan_furnitures", 840, 581},
    {"lab_e", 875, 685},
    {"lab_ipa_furnitures", 864, 768},
    {"sistD", 1720, 580},
};

TEST(SharedMapsTest, EveryAreaGraphInputMapImports) {
  if (!HaveSharedData()) GTEST_SKIP() << "no ../shared/data";
  TempDir dir;
  const std::string store = dir.File("store.db");
  for (const SharedMap& map : kMaps) {
    SCOPED_TRACE(map.name);
    std::vector<std::string> args = {"--store", store};
    // intel_map draws its walls grey 127 (free is 255, the halo around walls
    // 230): with the default occupied_max_grey of 100 it has no occupied
    // cells at all. 127 cannot be the default: lab_a's unknown is 127 too.
    if (map.name == "intel_map") args.insert(args.end(), {"--set", "import.occupied_max_grey=200"});
    args.push_back(SharedDataPath("areagraph/input/" + map.name + ".png"));
    const testing::CommandResult run = RunTool("ag-import", args);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err, "");

    const proto::GridMap grid = testing::ReadHeadGridMap(store, map.name);
    EXPECT_EQ(grid.frame().width_px(), map.width);
    EXPECT_EQ(grid.frame().height_px(), map.height);
    const CellCounts counts = CountCells(grid.cells());
    const double cells = static_cast<double>(map.width) * map.height;
    // Maps whose outside was repainted white (lab_c, lab_d, lab_e,
    // lab_ipa_furnitures, Freiburg101_scan_furnitures_trashbins) are up to
    // 98.5 % free; scans with a large unknown outside down to 26 %.
    EXPECT_GT(counts.free / cells, 0.10);
    EXPECT_LT(counts.free / cells, 0.99);
    // Walls: 0.8 % (Freiburg101) to 15 % (freiburg_building79).
    EXPECT_GT(counts.occupied / cells, 0.005);
    EXPECT_LT(counts.occupied / cells, 0.20);
    EXPECT_LT(counts.unknown / cells, 0.80);
  }
}

TEST(SharedMapsTest, IntelMapWithDefaultsWarnsAboutMissingWalls) {
  if (!HaveSharedData()) GTEST_SKIP() << "no ../shared/data";
  TempDir dir;
  const testing::CommandResult run =
      RunTool("ag-import",
              {"--store", dir.File("store.db"), SharedDataPath("areagraph/input/intel_map.png")});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find(" 0 occupied,"), std::string::npos) << run.out;
  EXPECT_NE(run.err.find("warning: map 'intel_map' has no occupied cells"), std::string::npos);
}

}  // namespace
}  // namespace areagraph
