// Which artifacts a viewer page shows, and how a second run shares the
// first one's layers.
#include "tools/export/viewer_run.h"

#include <gtest/gtest.h>

#include <memory>

#include "common/error.h"
#include "proto/artifacts.pb.h"
#include "proto/pipeline_options.pb.h"
#include "stages/pipeline/stage.h"
#include "tests/support/test_support.h"
#include "tests/tools/export/test_area_graph.h"
#include "tools/export/html_viewer.h"

namespace areagraph {
namespace {

// A store with a hand-made chain import -> clean -> merge for map "house"
// (merge reads clean directly here; the walk follows whatever keys are
// stored).
class ViewerRun : public ::testing::Test {
 protected:
  void SetUp() override {
    store_ = OpenArtifactStore(":memory:");
    grid_.set_format_version(1);
    *grid_.mutable_frame() = testing::TwoRoomAreaGraph().frame();
    grid_.set_cells(std::string(40 * 20, static_cast<char>(proto::CELL_FREE)));
    import_key_ = Run(kImportStage, {}, "file-digest", grid_);
    clean_key_ = RunClean({});
    merge_key_ = RunMerge(clean_key_, {});
  }

  // Stores `result` as the artifact of `stage` with one input key.
  std::string Run(const StageInfo& stage, const proto::PipelineOptions& options,
                  const std::string& input_key, const google::protobuf::Message& result) {
    StageInputs inputs;
    inputs.digests = {input_key};
    return RunCachedStage(*store_, "house", StageOf(stage), options, inputs,
                          [&] {
                            MessagePtr copy(result.New());
                            copy->CopyFrom(result);
                            return copy;
                          })
        .cache_key;
  }

  std::string RunClean(const proto::PipelineOptions& options) {
    proto::CleanedMap cleaned;
    *cleaned.mutable_frame() = grid_.frame();
    cleaned.set_cells(grid_.cells());
    return Run(kCleanStage, options, import_key_, cleaned);
  }

  std::string RunMerge(const std::string& clean_key, const proto::PipelineOptions& options) {
    return Run(kMergeStage, options, clean_key, testing::TwoRoomAreaGraph());
  }

  std::unique_ptr<ArtifactStore> store_;
  proto::GridMap grid_;
  std::string import_key_, clean_key_, merge_key_;
};

std::vector<std::string> KeysOf(const std::vector<ArtifactRecord>& artifacts) {
  std::vector<std::string> keys;
  for (const ArtifactRecord& artifact : artifacts) keys.push_back(artifact.cache_key);
  return keys;
}

TEST_F(ViewerRun, FollowsInputKeysNotTheHeadsOfEarlierStages) {
  proto::PipelineOptions other;
  other.mutable_clean()->set_outlier_percent(3);
  const std::string newer_clean = RunClean(other);  // now the clean head
  const auto artifacts = RunArtifacts(*store_, "house", "");
  EXPECT_EQ(KeysOf(artifacts), (std::vector<std::string>{import_key_, clean_key_, merge_key_}));
  // A key prefix of the newer clean artifact: the run up to clean.
  EXPECT_EQ(KeysOf(RunArtifacts(*store_, "house", newer_clean.substr(0, 8))),
            (std::vector<std::string>{import_key_, newer_clean}));
}

TEST_F(ViewerRun, UnknownMapOrKeyIsAnInputError) {
  EXPECT_THROW(RunArtifacts(*store_, "nowhere", ""), InputError);
  EXPECT_THROW(RunArtifacts(*store_, "house", "ffffffffff"), InputError);
}

TEST_F(ViewerRun, LayersOfEveryStagePresent) {
  const viewer::Run run = ViewerRunOf(RunArtifacts(*store_, "house", ""), "A");
  ASSERT_EQ(run.stages_size(), 3);
  EXPECT_EQ(run.stages(0).stage(), "import");
  EXPECT_EQ(run.stages(2).cache_key(), merge_key_);
  EXPECT_FALSE(run.grid_png().empty());
  EXPECT_TRUE(run.has_clean());
  EXPECT_FALSE(run.has_voronoi());
  EXPECT_EQ(run.area_graph().areas_size(), 2);
  EXPECT_FALSE(run.stages(1).options().empty());
}

TEST_F(ViewerRun, SecondRunLeavesOutTheLayersItShares) {
  proto::PipelineOptions other;
  other.mutable_merge()->set_min_area_m2(1);
  const std::string other_merge = RunMerge(clean_key_, other);
  const viewer::Run first = ViewerRunOf(RunArtifacts(*store_, "house", merge_key_), "A");
  const viewer::Run second = ViewerRunOf(RunArtifacts(*store_, "house", other_merge), "B", &first);
  ASSERT_EQ(second.stages_size(), 3);
  EXPECT_TRUE(second.stages(0).same_as_first());
  EXPECT_TRUE(second.stages(1).same_as_first());
  EXPECT_FALSE(second.stages(2).same_as_first());
  EXPECT_TRUE(second.grid_png().empty());
  EXPECT_FALSE(second.has_clean());
  EXPECT_EQ(second.area_graph().areas_size(), 2);
  bool min_area_marked = false;
  for (const viewer::OptionValue& value : second.stages(2).options()) {
    if (value.name() == "min_area_m2") min_area_marked = !value.is_default();
  }
  EXPECT_TRUE(min_area_marked);
}

TEST_F(ViewerRun, PageCarriesTheFrameAndOneJsonBlob) {
  const viewer::Page page = BuildViewerPage(*store_, "house", "", "");
  EXPECT_EQ(page.frame().width_px(), 40);
  EXPECT_EQ(page.runs_size(), 1);
  const std::string html = ViewerPageHtml(page);
  EXPECT_EQ(html.find("{{"), std::string::npos);
  EXPECT_NE(html.find("<title>house - areagraph</title>"), std::string::npos);
  EXPECT_NE(html.find("\"map_name\":\"house\""), std::string::npos);
  EXPECT_NE(html.find("Content-Security-Policy"), std::string::npos);
  // Nothing to fetch: the only URL is the SVG namespace that the script uses.
  EXPECT_EQ(testing::CountOccurrences(html, "://"),
            testing::CountOccurrences(html, "http://www.w3.org/2000/svg"));
  EXPECT_EQ(html.find(" src="), std::string::npos);
}

}  // namespace
}  // namespace areagraph
