// ag-export --format html from the command line: what it writes from a store
// that holds only an Area Graph, and one line for each mistake.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "proto/pipeline_options.pb.h"
#include "stages/pipeline/stage.h"
#include "store/artifact_store.h"
#include "tests/support/test_support.h"
#include "tests/tools/export/test_area_graph.h"

namespace areagraph {
namespace {

using testing::CountLines;
using testing::ReadFile;
using testing::RunTool;
using testing::TempDir;

class ViewerCli : public ::testing::Test {
 protected:
  void SetUp() override {
    std::unique_ptr<ArtifactStore> store = OpenArtifactStore(store_path_);
    StageInputs inputs;
    inputs.digests = {"cut-artifact-digest"};  // not in the store: merge is all there is
    merge_key_ = RunCachedStage(*store, "house", StageOf(kMergeStage), {}, inputs, [] {
                   return std::make_unique<proto::AreaGraph>(testing::TwoRoomAreaGraph());
                 }).cache_key;
  }

  testing::CommandResult Export(std::vector<std::string> extra) {
    std::vector<std::string> args = {"--store", store_path_, "--map", "house", "--out", page_};
    args.insert(args.end(), extra.begin(), extra.end());
    return RunTool("ag-export", args);
  }

  TempDir dir_;
  const std::string store_path_ = dir_.File("areagraph.db");
  const std::string page_ = dir_.File("house.html");
  std::string merge_key_;
};

TEST_F(ViewerCli, PageOfAStoreWithOnlyTheAreaGraph) {
  const auto run = Export({"--format", "html"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string page = ReadFile(page_);
  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(page.find("\"map_name\":\"house\""), std::string::npos);
  EXPECT_NE(page.find("\"cache_key\":\"" + merge_key_ + "\""), std::string::npos);
  EXPECT_EQ(page.find("\"grid_png\""), std::string::npos);  // no import artifact to draw
}

TEST_F(ViewerCli, KeyPrefixPicksTheRunAndAnUnknownKeyIsOneLine) {
  EXPECT_EQ(Export({"--format", "html", "--key", merge_key_.substr(0, 6)}).exit_code, 0);
  const auto unknown = Export({"--format", "html", "--compare", "ffffffff"});
  EXPECT_EQ(unknown.exit_code, 1);
  EXPECT_EQ(CountLines(unknown.err), 1) << unknown.err;
  EXPECT_NE(unknown.err.find("ffffffff"), std::string::npos) << unknown.err;
}

TEST_F(ViewerCli, KeyWithAnotherFormatIsOneLine) {
  const auto run = Export({"--format", "json", "--key", merge_key_.substr(0, 6)});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(CountLines(run.err), 1) << run.err;
  EXPECT_NE(run.err.find("--format html"), std::string::npos) << run.err;
}

TEST_F(ViewerCli, UnknownMapIsOneLine) {
  const auto run = RunTool(
      "ag-export", {"--store", store_path_, "--map", "castle", "--format", "html", "--out", page_});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(CountLines(run.err), 1) << run.err;
  EXPECT_NE(run.err.find("castle"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace areagraph
