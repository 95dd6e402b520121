// Inputs that are not what they seem: a FIFO where a file is read (it hung
// every tool for ever), a name with a NUL byte, an options file with a
// byte-order mark, and map names that break the one rule for them.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <string>
#include <vector>

#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

// A tool that still waits after this long would have waited for ever.
CommandResult RunWithin(const std::string& tool, const std::vector<std::string>& args) {
  std::vector<std::string> argv = {"timeout", "60", BinDir() + "/" + tool};
  argv.insert(argv.end(), args.begin(), args.end());
  return RunProgram(argv);
}

void ExpectOneLineError(const CommandResult& result, const std::string& needle,
                        const std::string& what) {
  EXPECT_EQ(result.exit_code, 1) << what << " (124: it hung): " << result.err;
  EXPECT_EQ(CountLines(result.err), 1) << what << ": " << result.err;
  EXPECT_NE(result.err.find(needle), std::string::npos) << what << ": " << result.err;
}

class SpecialInputCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(mkfifo(fifo_png_.c_str(), 0600), 0);
    ASSERT_EQ(mkfifo(fifo_options_.c_str(), 0600), 0);
    std::filesystem::copy_file(SourcePath("examples/two_rooms.png"), map_);
  }

  TempDir dir_;
  const std::string store_ = dir_.File("s.db");
  const std::string fifo_png_ = dir_.File("pipe.png");
  const std::string fifo_options_ = dir_.File("fifo.pbtxt");
  const std::string map_ = dir_.File("two_rooms.png");
};

TEST_F(SpecialInputCliTest, FifoAsImageOrYamlImageIsRefusedAtOnce) {
  ExpectOneLineError(RunWithin("ag-import", {"--store", store_, fifo_png_}),
                     "cannot read image '" + fifo_png_ + "': it is a FIFO (named pipe)",
                     "ag-import pipe.png");
  WriteFile(dir_.File("pipe.yaml"), "image: pipe.png\nresolution: 0.05\n");
  ExpectOneLineError(RunWithin("ag-import", {"--store", store_, dir_.File("pipe.yaml")}),
                     "it is a FIFO (named pipe), not a regular file", "YAML naming a FIFO");
  EXPECT_FALSE(std::filesystem::exists(store_));
}

TEST_F(SpecialInputCliTest, FifoAsOptionsFileIsRefusedByEveryTool) {
  const std::string refused = "cannot read options file '" + fifo_options_ + "': it is a FIFO";
  ASSERT_EQ(RunTool("ag-import", {"--store", store_, map_}).exit_code, 0);
  const std::vector<std::string> options = {"--options", fifo_options_};
  const std::vector<std::string> on_map = {"--store",   store_,      "--map",
                                           "two_rooms", "--options", fifo_options_};
  ExpectOneLineError(RunWithin("ag-import", {"--store", store_, "--options", fifo_options_, map_}),
                     refused, "ag-import");
  for (const std::string& stage :
       {"ag-clean", "ag-voronoi", "ag-prune", "ag-cut", "ag-merge", "ag-match", "ag-pipeline"}) {
    ExpectOneLineError(RunWithin(stage, on_map), refused, stage);
  }
  ExpectOneLineError(RunWithin("ag-run", {"--store", store_, "--options", fifo_options_, map_}),
                     refused, "ag-run");
  ExpectOneLineError(RunWithin("ag-run", {"--print-options", "--options", fifo_options_}), refused,
                     "ag-run --print-options");
  ExpectOneLineError(RunWithin("ag-live", {"--store", store_, "--options", fifo_options_}), refused,
                     "ag-live");
}

// A FIFO found in a folder was skipped without a word; one given by name
// fails as its map, and the others go on.
TEST_F(SpecialInputCliTest, FifoInAFolderIsSkippedWithALine) {
  const CommandResult run = RunWithin("ag-run", {"--store", store_, dir_.path()});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("ag-run: skipping '" + fifo_png_ +
                         "': it is a FIFO (named pipe), not a regular file"),
            std::string::npos)
      << run.err;
  const CommandResult named = RunWithin("ag-run", {"--store", store_, fifo_png_, map_});
  EXPECT_EQ(named.exit_code, 1) << named.err;
  EXPECT_NE(named.out.find("it is a FIFO"), std::string::npos) << named.out;
}

// The issue's `image: "map.png\0.txt"` was read as map.png.
TEST_F(SpecialInputCliTest, YamlImageWithANulByteIsRefused) {
  WriteFile(dir_.File("nul.yaml"), "image: \"two_rooms.png\\0.txt\"\nresolution: 0.05\n");
  ExpectOneLineError(RunWithin("ag-import", {"--store", store_, dir_.File("nul.yaml")}),
                     "'image' holds a NUL byte", "image with NUL");
}

// It failed with "non ascii codepoint 239".
TEST_F(SpecialInputCliTest, OptionsFileWithAByteOrderMarkIsRead) {
  const std::string options = dir_.File("bom.pbtxt");
  WriteFile(options,
            "\xEF\xBB\xBF"
            "cut { room_width_m: 1.1 }\n");
  const CommandResult printed = RunWithin("ag-run", {"--print-options", "--options", options});
  EXPECT_EQ(printed.exit_code, 0) << printed.err;
  EXPECT_NE(printed.out.find("room_width_m: 1.1"), std::string::npos) << printed.out;
}

// Names ag-live refused were taken by ag-import, ag-run and manifests.
TEST_F(SpecialInputCliTest, MapNamesFollowOneRuleEverywhere) {
  for (const std::string& name : {"..", "/abs", "a b", "a\tb", "a\nb", "x/../../y"}) {
    const CommandResult import = RunWithin("ag-import", {"--store", store_, "--name", name, map_});
    ExpectOneLineError(import, "map name '", "ag-import --name");
  }
  EXPECT_FALSE(std::filesystem::exists(store_));
  WriteFile(dir_.File("maps.csv"), "path,name\ntwo_rooms.png,my map\n");
  ExpectOneLineError(RunWithin("ag-run", {"--store", store_, dir_.File("maps.csv")}),
                     "maps.csv:2: map name 'my map' holds a blank", "manifest");
  const std::string folder = dir_.File("folder");
  std::filesystem::create_directory(folder);
  std::filesystem::copy_file(map_, folder + "/my map.png");
  ExpectOneLineError(RunWithin("ag-run", {"--store", store_, folder}),
                     "map name 'my map' holds a blank", "folder");
  EXPECT_FALSE(std::filesystem::exists(store_));
}

}  // namespace
}  // namespace areagraph::testing
