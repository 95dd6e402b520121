// ag-run decides "fully cached" from keys it computes without reading any
// artifact; these must be the keys the stages really store.
#include <gtest/gtest.h>

#include "stages/import/import_stage.h"
#include "stages/pipeline/map_pipeline.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

TEST(PipelineKeysTest, PlannedKeysAreTheStoredKeys) {
  const auto store = OpenArtifactStore(":memory:");
  const ImportSource source = ReadImportSource(testing::SourcePath("examples/two_rooms.png"));
  proto::PipelineOptions options;
  const StageRun import = RunCachedStage(
      *store, "m", StageOf(kImportStage), options, ImportInputs(source),
      [&] { return std::make_unique<proto::GridMap>(ImportGridMap(source, options.import())); });
  EXPECT_EQ(import.cache_key, ImportCacheKey(source, options.import()));
  std::vector<std::string> stored;
  RunMapPipeline(*store, "m", options, false,
                 [&](const StageInfo&, const StageRun& run) { stored.push_back(run.cache_key); });
  EXPECT_EQ(stored, PlanPipelineKeys(import.cache_key, options));
  for (size_t i = 0; i < stored.size(); ++i) {
    EXPECT_EQ(store->ReadHeadKey("m", PipelineStages()[i].name), stored[i]);
  }
}

TEST(PipelineKeysTest, StageOptionChangesThatStageAndLaterOnes) {
  proto::PipelineOptions options;
  const std::vector<std::string> before = PlanPipelineKeys("import-key", options);
  options.mutable_cut()->set_room_width_m(1.7);
  const std::vector<std::string> after = PlanPipelineKeys("import-key", options);
  // clean, voronoi, prune unchanged; cut and merge changed.
  for (size_t i = 0; i < 3; ++i) EXPECT_EQ(before[i], after[i]) << i;
  for (size_t i = 3; i < 5; ++i) EXPECT_NE(before[i], after[i]) << i;
  EXPECT_NE(PlanPipelineKeys("other-import", options)[0], after[0]);
}

TEST(PipelineKeysTest, BumpedStageVersionChangesItsKey) {
  const proto::PipelineOptions options;
  const StageInfo bumped{kCutStage.name, kCutStage.version + 1};
  EXPECT_NE(StageCacheKey(kCutStage, options.cut(), {"a", "b"}),
            StageCacheKey(bumped, options.cut(), {"a", "b"}));
  // Every key enters the keys of the stages that read it.
  EXPECT_NE(StageCacheKey(kMergeStage, options.merge(), {"cut-1", "clean"}),
            StageCacheKey(kMergeStage, options.merge(), {"cut-2", "clean"}));
}

TEST(PipelineKeysTest, ExplicitDefaultsGiveTheSameKeys) {
  proto::PipelineOptions explicit_defaults;
  explicit_defaults.mutable_prune()->set_min_clearance_m(
      explicit_defaults.prune().min_clearance_m());
  EXPECT_EQ(PlanPipelineKeys("k", proto::PipelineOptions()),
            PlanPipelineKeys("k", explicit_defaults));
}

}  // namespace
}  // namespace areagraph
