// examples/python: the store read from Python through the package areagraph
// (from the build tree), and the Area Graph as a networkx MultiGraph.
#include <gtest/gtest.h>

#include <regex>

#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

// Debian's interpreter, for which the package is built and which has
// python3-networkx (tools/install-deps.sh); another python3 on PATH may not.
constexpr char kPython[] = "/usr/bin/python3";

class PythonExampleTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const CommandResult run = RunTool(
        "ag-run", {"--store", store_, "--jobs", "1", SourcePath("examples/office_small.png"),
                   SourcePath("examples/two_rooms.png")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
  }
  CommandResult Show(std::vector<std::string> extra) const {
    std::vector<std::string> argv = {
        "/usr/bin/env", "PYTHONPATH=" AG_PYTHON_PACKAGE_DIR,
        kPython,        SourcePath("examples/python/show_area_graph.py"),
        "--store",      store_};
    argv.insert(argv.end(), extra.begin(), extra.end());
    return RunProgram(argv);
  }
  TempDir dir_;
  const std::string store_ = dir_.File("s.db");
};

TEST_F(PythonExampleTest, SummaryMatchesTheStoredAreaGraph) {
  const CommandResult inspect =
      RunTool("ag-inspect", {"--store", store_, "--map", "office_small", "--stage", "match"});
  ASSERT_EQ(inspect.exit_code, 0) << inspect.err;
  std::smatch counts;
  ASSERT_TRUE(std::regex_search(inspect.out, counts, std::regex("(\\d+) areas, (\\d+) passages")))
      << inspect.out;

  const CommandResult shown = Show({"--map", "office_small"});
  ASSERT_EQ(shown.exit_code, 0) << shown.err;
  EXPECT_EQ(shown.out.rfind("office_small: " + counts[1].str() + " areas, " + counts[2].str() +
                                " passages, 1 connected part(s)\n",
                            0),
            0u)
      << shown.out;
  EXPECT_EQ(CountLines(shown.out), 1 + std::stoi(counts[1].str())) << shown.out;
  EXPECT_NE(shown.out.find("area 0: room, "), std::string::npos) << shown.out;
}

TEST_F(PythonExampleTest, NodeLinkJsonIsAnUndirectedMultigraph) {
  const CommandResult shown = Show({"--map", "two_rooms", "--json"});
  ASSERT_EQ(shown.exit_code, 0) << shown.err;
  EXPECT_NE(shown.out.find("\"directed\": false"), std::string::npos) << shown.out;
  EXPECT_NE(shown.out.find("\"multigraph\": true"), std::string::npos) << shown.out;
  EXPECT_NE(shown.out.find("\"kind\": \"room\""), std::string::npos) << shown.out;
  EXPECT_NE(shown.out.find("\"width_m\": "), std::string::npos) << shown.out;
  // The newest graph is ag-match's: its stable ids and version come along.
  EXPECT_NE(shown.out.find("\"stable_id\": "), std::string::npos) << shown.out;
  EXPECT_NE(shown.out.find("\"version\": 1"), std::string::npos) << shown.out;
}

TEST_F(PythonExampleTest, UnknownMapIsOneLineError) {
  const CommandResult shown = Show({"--map", "nowhere"});
  EXPECT_EQ(shown.exit_code, 1);
  EXPECT_EQ(shown.err, "show_area_graph: map 'nowhere' is not in the store\n");
}

}  // namespace
}  // namespace areagraph::testing
