// ag-clean and ag-voronoi as executables, on an example map.
#include <gtest/gtest.h>

#include "tests/support/raw_sqlite.h"
#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

class StageTools : public ::testing::Test {
 protected:
  void SetUp() override {
    store_ = dir_.File("store.db");
    const CommandResult import =
        RunTool("ag-import", {"--store", store_, SourcePath("examples/two_rooms.png")});
    ASSERT_EQ(import.exit_code, 0) << import.err;
  }
  CommandResult Run(const std::string& tool, std::vector<std::string> extra = {}) {
    std::vector<std::string> args = {"--store", store_, "--map", "two_rooms"};
    args.insert(args.end(), extra.begin(), extra.end());
    return RunTool(tool, args);
  }

  TempDir dir_;
  std::string store_;
};

TEST_F(StageTools, CleanThenVoronoiComputeOnceAndThenHitTheCache) {
  CommandResult clean = Run("ag-clean");
  ASSERT_EQ(clean.exit_code, 0) << clean.err;
  EXPECT_EQ(CountLines(clean.out), 1);
  EXPECT_NE(clean.out.find("map 'two_rooms'"), std::string::npos) << clean.out;
  EXPECT_NE(clean.out.find("(computed)"), std::string::npos) << clean.out;

  CommandResult voronoi = Run("ag-voronoi");
  ASSERT_EQ(voronoi.exit_code, 0) << voronoi.err;
  EXPECT_EQ(CountLines(voronoi.out), 1);
  EXPECT_NE(voronoi.out.find(" sites, "), std::string::npos) << voronoi.out;
  EXPECT_NE(voronoi.out.find("(computed)"), std::string::npos) << voronoi.out;

  voronoi = Run("ag-voronoi");
  ASSERT_EQ(voronoi.exit_code, 0) << voronoi.err;
  EXPECT_NE(voronoi.out.find("(cached)"), std::string::npos) << voronoi.out;

  // New clean options change clean's key and therefore voronoi's.
  clean = Run("ag-clean", {"--set", "clean.robot_width_m=0.6"});
  ASSERT_EQ(clean.exit_code, 0) << clean.err;
  EXPECT_NE(clean.out.find("(computed)"), std::string::npos) << clean.out;
  voronoi = Run("ag-voronoi");
  EXPECT_NE(voronoi.out.find("(computed)"), std::string::npos) << voronoi.out;
}

TEST_F(StageTools, BadOptionsAndMissingInputsFailWithOneLine) {
  CommandResult result = Run("ag-clean", {"--set", "clean.outlier_percent=-3"});
  EXPECT_EQ(result.exit_code, 2);  // a bad option is bad usage
  EXPECT_EQ(result.err,
            "ag-clean: option 'clean.outlier_percent' must be a number of percent in [0, 100], got "
            "-3\n");

  result = Run("ag-voronoi");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(CountLines(result.err), 1);
  EXPECT_NE(result.err.find("run ag-clean first"), std::string::npos) << result.err;

  result = RunTool("ag-clean", {"--store", store_, "--map", "nosuch"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("map 'nosuch', clean: the map is not in the store"), std::string::npos)
      << result.err;
}

TEST_F(StageTools, CacheHitPrintsTheStoredSummaryWithoutReadingThePayload) {
  ASSERT_EQ(Run("ag-clean").exit_code, 0);
  const CommandResult computed = Run("ag-voronoi");
  ASSERT_EQ(computed.exit_code, 0) << computed.err;
  const std::string summary = computed.out.substr(computed.out.find("': ") + 3);
  ASSERT_NE(summary.find(" sites, "), std::string::npos) << computed.out;
  const std::string key = QueryColumn(store_,
                                      "SELECT cache_key FROM artifacts WHERE stage = "
                                      "'voronoi'")
                              .at(0);
  // A damaged payload would fail any parse; the hit must not need one.
  FlipPayloadByte(store_, key, 3);
  const CommandResult cached = Run("ag-voronoi");
  ASSERT_EQ(cached.exit_code, 0) << cached.err;
  EXPECT_NE(cached.out.find("(cached)"), std::string::npos) << cached.out;
  const std::string sites = summary.substr(0, summary.find(" sites, "));
  EXPECT_NE(cached.out.find(sites + " sites, "), std::string::npos) << cached.out;
}

TEST_F(StageTools, HelpExitsZero) {
  for (const char* tool : {"ag-clean", "ag-voronoi"}) {
    const CommandResult help = RunTool(tool, {"--help"});
    EXPECT_EQ(help.exit_code, 0) << tool;
    EXPECT_NE(help.out.find("--store"), std::string::npos) << tool;
  }
}

}  // namespace
}  // namespace areagraph::testing
