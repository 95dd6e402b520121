// The stages on a write-behind store (ag-run's workers, ag-pipeline): each
// artifact is written while the next stage computes, with the same result
// and the same errors as when every write is done at once.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "common/error.h"
#include "stages/import/import_stage.h"
#include "stages/pipeline/artifact_memo.h"
#include "stages/pipeline/map_pipeline.h"
#include "store/write_behind_store.h"
#include "tests/support/raw_sqlite.h"
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

// Every artifact over 0 bytes taken the big artifacts' way: each result held
// by the store's thread as the message itself while the next stage computes,
// and cut, which takes prune's graph over, waits for that write first.
TEST(WriteBehindPipelineTest, ArtifactsHeldAsMessagesStoreWhatADirectStoreStores) {
  testing::TempDir dir;
  const std::string direct_path = dir.File("direct.db"), behind_path = dir.File("behind.db");
  const auto direct = RunTwoRooms(direct_path, *OpenArtifactStore(direct_path));
  const std::unique_ptr<ArtifactStore> behind = OpenWriteBehindStore(behind_path, 0);
  EXPECT_EQ(RunTwoRooms(behind_path, *behind), direct);
}

bool taker_got_its_input = false;

// A stage that takes its input over (cut, prune's graph) gets it even while
// the store's thread still holds it for a write: the take waits for that
// write (held up here by another connection's lock for 300 ms).
TEST(WriteBehindPipelineTest, AStageTakesOverAnInputWhoseWriteIsPending) {
  testing::TempDir dir;
  const std::string path = dir.File("store.db");
  const std::unique_ptr<ArtifactStore> store = OpenWriteBehindStore(path, 0);
  const proto::PipelineOptions options;
  const ImportSource source = ReadImportSource(testing::SourcePath("examples/two_rooms.png"));
  RunCachedStage(*store, "m", StageOf(kImportStage), options, ImportInputs(source), [&] {
    return std::make_unique<proto::GridMap>(ImportGridMap(source, options.import()));
  });
  ArtifactMemo memo;
  RunMapPipeline(*store, "m", options, false, PipelineObserver{}, kCleanStage, kPruneStage, &memo);
  const std::string prune_key = store->ReadHeadKey("m", kPruneStage.name).value();
  std::shared_ptr<const google::protobuf::Message> graph =
      memo.Acquire(kPruneStage.name, prune_key);
  ASSERT_NE(graph, nullptr);

  testing::WriteLockHolder lock(path);
  NewArtifact again;
  again.map_name = "m";
  again.stage = kPruneStage.name;
  again.cache_key = prune_key + "-again";
  again.input_keys = {"voronoi key", "clean key"};
  again.proto_type = "areagraph.proto.TopologyGraph";
  again.stage_version = kPruneStage.version;
  store->WriteSharedMessageArtifact(again, graph);
  memo.Keep(kPruneStage.name, again.cache_key, std::move(graph));
  memo.MarkLastRead(kPruneStage.name);
  std::thread release([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    lock.Release();
  });
  StageDefinition taker = StageOf(kCutStage);
  taker.compute = [](const std::vector<const google::protobuf::Message*>&,
                     const InputRelease& input_release, const proto::PipelineOptions&) {
    taker_got_its_input = input_release.TakeInput(0) != nullptr;
    return MessagePtr(std::make_unique<proto::CutGraph>());
  };
  RunStageOnHeads(*store, "m", taker, options, false, &memo);
  release.join();
  store->FinishWrites();
  EXPECT_TRUE(taker_got_its_input);
  EXPECT_EQ(store->ReadHeadKey("m", kPruneStage.name), again.cache_key);
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
