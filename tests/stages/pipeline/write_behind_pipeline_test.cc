// The stages on a write-behind store (ag-run's workers, ag-pipeline): each
// artifact is written while the next stage computes, with the same result
// and the same errors as when every write is done at once.
#include <gtest/gtest.h>

#include "common/error.h"
#include "stages/import/import_stage.h"
#include "stages/pipeline/map_pipeline.h"
#include "store/write_behind_store.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

// Every stage of two_rooms on `store`; the (stage, digest) of each artifact.
std::vector<std::pair<std::string, std::string>> RunTwoRooms(const std::string& path,
                                                             ArtifactStore& store) {
  const proto::PipelineOptions options;
  const ImportSource source = ReadImportSource(testing::SourcePath("examples/two_rooms.png"));
  RunCachedStage(store, "m", StageOf(kImportStage), options, ImportInputs(source), [&] {
    return std::make_unique<proto::GridMap>(ImportGridMap(source, options.import()));
  });
  RunMapPipeline(store, "m", options, false, nullptr);
  std::vector<std::pair<std::string, std::string>> digests;
  for (const ArtifactRecord& row :
       OpenArtifactStore(path, StoreMode::kReadOnly)->ReadArtifactSummaries("m")) {
    digests.emplace_back(row.stage, row.payload_digest);
  }
  return digests;
}

// RunMapPipeline returns once everything is stored: another connection sees
// every stage, with the digests of a store that writes at once.
TEST(WriteBehindPipelineTest, StoresWhatADirectStoreStores) {
  testing::TempDir dir;
  const std::string direct_path = dir.File("direct.db"), behind_path = dir.File("behind.db");
  const auto direct = RunTwoRooms(direct_path, *OpenArtifactStore(direct_path));
  const std::unique_ptr<ArtifactStore> behind = OpenWriteBehindStore(behind_path);
  EXPECT_EQ(RunTwoRooms(behind_path, *behind), direct);
  EXPECT_EQ(direct.size(), StageTable().size());
}

// Run one by one, a stage whose write failed stops the map before the next
// stage runs: the next stage's own failure must not hide it.
TEST(WriteBehindPipelineTest, AnEarlierStagesFailedWriteIsTheMapsError) {
  testing::TempDir dir;
  const std::unique_ptr<ArtifactStore> store = OpenWriteBehindStore(dir.File("store.db"));
  proto::GridMap grid;
  grid.set_format_version(kGridMapFormatVersion);
  StageInputs inputs;
  inputs.digests = {"a key\nthe store refuses"};
  RunCachedStage(*store, "m", StageOf(kImportStage), {}, inputs,
                 [&] { return std::make_unique<proto::GridMap>(grid); });
  inputs.digests = {"import key"};
  try {
    RunCachedStage(*store, "m", StageOf(kCleanStage), {}, inputs,
                   []() -> MessagePtr { throw InputError("clean failed too"); });
    FAIL() << "no error";
  } catch (const MapStepError& error) {
    EXPECT_EQ(error.step(), "import") << error.what();
    EXPECT_NE(error.cause().find("line break"), std::string::npos) << error.what();
  }
  EXPECT_EQ(store->ReadHeadKey("m", "import"), std::nullopt);
}

}  // namespace
}  // namespace areagraph
