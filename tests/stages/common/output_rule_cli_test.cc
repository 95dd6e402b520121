// One rule for where every tool's output goes (README, "Where output goes"):
// what was asked for on standard output, how it went on standard error, and
// `wrote FILE` from every tool that writes a file, unless the file is
// standard output. ag-export used to print nothing while ag-render printed
// "wrote".
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

std::string Shown(const std::string& tool, const std::vector<std::string>& args) {
  std::string text = tool;
  for (const std::string& arg : args) text += " " + arg;
  return text;
}

class OutputRuleCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const CommandResult run =
        RunTool("ag-run", {"--store", store_, SourcePath("examples/two_rooms.png")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
  }

  TempDir dir_;
  const std::string store_ = dir_.File("s.db");
};

TEST_F(OutputRuleCliTest, EveryFileWriterSaysWhatItWroteOnStandardOutput) {
  std::vector<std::pair<std::string, std::vector<std::string>>> writers;
  for (const std::string& format :
       {"labels", "preview", "geojson", "osmag", "json", "protojson", "html"}) {
    writers.push_back({"ag-export",
                       {"--store", store_, "--map", "two_rooms", "--format", format, "--out",
                        dir_.File("out-" + format)}});
  }
  writers.push_back(
      {"ag-render", {"--store", store_, "--map", "two_rooms", "--out", dir_.File("out.png")}});
  for (const auto& [tool, args] : writers) {
    const CommandResult result = RunTool(tool, args);
    EXPECT_EQ(result.exit_code, 0) << Shown(tool, args) << ": " << result.err;
    EXPECT_EQ(result.out, "wrote " + args.back() + "\n") << Shown(tool, args);
    EXPECT_EQ(result.err, "") << Shown(tool, args);
  }
}

TEST_F(OutputRuleCliTest, DataOnStandardOutputComesAlone) {
  const CommandResult json = RunTool(
      "ag-export", {"--store", store_, "--map", "two_rooms", "--format", "json", "--out", "-"});
  EXPECT_EQ(json.exit_code, 0) << json.err;
  EXPECT_EQ(json.out.rfind("{", 0), 0u) << json.out.substr(0, 80);
  EXPECT_EQ(json.out.find("wrote"), std::string::npos);
  EXPECT_EQ(json.err, "");
  const CommandResult png =
      RunTool("ag-render", {"--store", store_, "--map", "two_rooms", "--out", "-"});
  EXPECT_EQ(png.exit_code, 0) << png.err;
  EXPECT_EQ(png.out.rfind("\x89PNG", 0), 0u);
  EXPECT_EQ(png.err, "");
}

// Reports go to standard output; standard error stays empty, but for
// ag-run's line per map, which is progress.
TEST_F(OutputRuleCliTest, ReportsGoToStandardOutputAndProgressToStandardError) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> reporters = {
      {"ag-inspect", {"--store", store_}},
      {"ag-inspect", {"--store", store_, "--map", "two_rooms"}},
      {"ag-inspect", {"--store", store_, "--history", "two_rooms"}},
      {"ag-store", {"verify", "--store", store_}},
      {"ag-store", {"failures", "--store", store_}},
      {"ag-store", {"backup", "--store", store_, dir_.File("backup.db")}},
      {"ag-store", {"merge", dir_.File("merged.db"), store_}},
      {"ag-store", {"gc", "--store", store_}},
      {"ag-import", {"--store", store_, SourcePath("examples/two_rooms.png")}},
      {"ag-clean", {"--store", store_, "--map", "two_rooms"}},
      {"ag-pipeline", {"--store", store_, "--map", "two_rooms"}},
  };
  for (const auto& [tool, args] : reporters) {
    const CommandResult result = RunTool(tool, args);
    EXPECT_EQ(result.exit_code, 0) << Shown(tool, args) << ": " << result.err;
    EXPECT_GT(CountLines(result.out), 0) << Shown(tool, args);
    EXPECT_EQ(result.err, "") << Shown(tool, args);
  }
  const CommandResult run =
      RunTool("ag-run", {"--store", store_, SourcePath("examples/corridor_rooms.png")});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("maps"), std::string::npos) << run.out;
  std::istringstream progress(run.err);
  std::string line;
  int lines = 0;
  while (std::getline(progress, line)) {
    EXPECT_EQ(line.rfind("ag-run: [1/1] corridor_rooms: ", 0), 0u) << line;
    ++lines;
  }
  EXPECT_EQ(lines, 1) << run.err;
}

}  // namespace
}  // namespace areagraph::testing
