// The write-behind store: what its caller reads while a write is pending,
// what it stores, and how a failed write is reported.

#include "store/write_behind_store.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "common/error.h"
#include "proto/artifacts.pb.h"
#include "store/digest.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

constexpr char kMap[] = "behind";

NewArtifact Row(const std::string& stage, const std::string& key) {
  NewArtifact artifact;
  artifact.map_name = kMap;
  artifact.stage = stage;
  artifact.cache_key = key;
  artifact.input_keys = {"input of " + key};
  artifact.proto_type = "areagraph.proto.GridMap";
  artifact.summary_line = stage + " summary";
  return artifact;
}

// A grid of `cells` bytes, a pattern that depends on `seed`.
proto::GridMap Grid(size_t cells, int seed) {
  proto::GridMap grid;
  grid.set_format_version(1);
  grid.mutable_frame()->set_width_px(static_cast<int>(cells));
  std::string bytes(cells, '\0');
  for (size_t i = 0; i < cells; ++i) bytes[i] = static_cast<char>((i * 7 + seed * 131) % 251);
  grid.set_cells(bytes);
  return grid;
}

// The stored payload and digest of `key`, read by a connection of its own.
ArtifactRecord StoredArtifact(const std::string& path, const std::string& key) {
  const std::optional<ArtifactRecord> record =
      OpenArtifactStore(path, StoreMode::kReadOnly)->ReadArtifact(kMap, key);
  EXPECT_TRUE(record) << key;
  return record.value_or(ArtifactRecord{});
}

// The caller's next stage asks for the head and the key of what it just
// handed over, and a read of its payload waits for it.
TEST(WriteBehindStoreTest, PendingArtifactIsSeenByItsWriterAndStoredAsSerialized) {
  testing::TempDir dir;
  const std::string path = dir.File("store.db");
  const proto::GridMap grid = Grid(3 << 20, 1);
  {
    const std::unique_ptr<ArtifactStore> store = OpenWriteBehindStore(path);
    store->WriteMessageArtifact(Row("import", "k1"), grid);
    EXPECT_EQ(store->ReadHeadKey(kMap, "import"), "k1");
    EXPECT_TRUE(store->HasArtifact(kMap, "k1"));
    EXPECT_FALSE(store->HasArtifact(kMap, "k2"));
    EXPECT_EQ(store->ReadHeadKey(kMap, "clean"), std::nullopt);
    const std::optional<ArtifactRecord> read = store->ReadArtifact(kMap, "k1");
    ASSERT_TRUE(read);
    EXPECT_TRUE(read->payload == grid.SerializeAsString());
    EXPECT_EQ(read->summary_line, "import summary");
    EXPECT_EQ(store->ReadMap(kMap)->name, kMap);
  }
  const ArtifactRecord stored = StoredArtifact(path, "k1");
  EXPECT_EQ(stored.payload_digest, Sha256Hex(grid.SerializeAsString()));
  EXPECT_EQ(stored.input_keys, std::vector<std::string>{"input of k1"});
}

// The same digest as a store that writes at once, also for a payload that
// the latter streams (over kWholeEncodingMaxBytes) and one written in the
// caller's thread (over kWriteBehindMaxBytes).
TEST(WriteBehindStoreTest, DigestsEqualThoseOfADirectWrite) {
  testing::TempDir dir;
  for (const size_t cells :
       {size_t{100}, kWholeEncodingMaxBytes + 12345, kWriteBehindMaxBytes + 1}) {
    const proto::GridMap grid = Grid(cells, 2);
    const std::string key = "k" + std::to_string(cells);
    OpenArtifactStore(dir.File("direct.db"))->WriteMessageArtifact(Row("import", key), grid);
    const std::unique_ptr<ArtifactStore> behind = OpenWriteBehindStore(dir.File("behind.db"));
    behind->WriteMessageArtifact(Row("import", key), grid);
    behind->FinishWrites();
    const ArtifactRecord direct = StoredArtifact(dir.File("direct.db"), key);
    const ArtifactRecord written = StoredArtifact(dir.File("behind.db"), key);
    EXPECT_EQ(written.payload_digest, direct.payload_digest) << cells;
    EXPECT_TRUE(written.payload == direct.payload) << cells;
  }
}

// The message is serialized before the call returns: the caller may change
// or free it at once (cut takes over prune's graph).
TEST(WriteBehindStoreTest, MessageChangedAfterTheCallDoesNotReachTheStore) {
  testing::TempDir dir;
  const std::string path = dir.File("store.db");
  proto::GridMap grid = Grid(4 << 20, 3);
  const std::string original = grid.SerializeAsString();
  const std::unique_ptr<ArtifactStore> store = OpenWriteBehindStore(path);
  store->WriteMessageArtifact(Row("import", "k1"), grid);
  grid.set_cells(std::string(grid.cells().size(), 'x'));
  store->FinishWrites();
  EXPECT_EQ(StoredArtifact(path, "k1").payload_digest, Sha256Hex(original));
}

// Artifacts are written in the order handed over: each waits for the one
// before, so the store never holds a later stage without its input; also
// one too big for the thread (voronoi here) waits for the one pending.
TEST(WriteBehindStoreTest, WritesLandInOrderAndEachMovesItsHead) {
  testing::TempDir dir;
  const std::string path = dir.File("store.db");
  const std::unique_ptr<ArtifactStore> store = OpenWriteBehindStore(path);
  const char* stages[] = {"import", "clean", "voronoi", "prune"};
  for (int i = 0; i < 4; ++i) {
    const size_t cells = i == 2 ? kWriteBehindMaxBytes + 1 : size_t{1} << 20;
    store->WriteMessageArtifact(Row(stages[i], "k" + std::to_string(i)), Grid(cells, i));
  }
  store->FinishWrites();
  const std::vector<ArtifactRecord> rows =
      OpenArtifactStore(path, StoreMode::kReadOnly)->ReadArtifactSummaries(kMap);
  ASSERT_EQ(rows.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(rows[i].cache_key, "k" + std::to_string(i));  // oldest first
    EXPECT_TRUE(rows[i].is_head);
  }
}

// A write that fails in the thread is the error of its own map and stage,
// thrown by the next call that depends on it, once.
TEST(WriteBehindStoreTest, FailedWriteIsThrownOnceNamingItsStage) {
  testing::TempDir dir;
  const std::string path = dir.File("store.db");
  const std::unique_ptr<ArtifactStore> store = OpenWriteBehindStore(path);
  NewArtifact bad = Row("clean", "bad");
  bad.input_keys = {"two\nlines"};  // refused by the store
  store->WriteMessageArtifact(bad, Grid(100, 4));
  try {
    // A read of it waits for it: not "no such artifact", the write failed.
    store->ReadArtifact(kMap, "bad");
    FAIL() << "the failed write went unreported";
  } catch (const MapStepError& error) {
    EXPECT_EQ(error.map_name(), kMap);
    EXPECT_EQ(error.step(), "clean");
    EXPECT_NE(error.cause().find("line break"), std::string::npos) << error.cause();
  }
  EXPECT_NO_THROW(store->FinishWrites());
  EXPECT_EQ(store->ReadHeadKey(kMap, "clean"), std::nullopt);
  store->WriteMessageArtifact(Row("clean", "good"), Grid(100, 5));
  store->FinishWrites();
  EXPECT_EQ(StoredArtifact(path, "good").summary_line, "clean summary");
}

// The artifact handed over after a failed one is refused with the earlier
// error and never written.
TEST(WriteBehindStoreTest, WriteAfterAFailedOneThrowsItsErrorAndIsDropped) {
  testing::TempDir dir;
  const std::string path = dir.File("store.db");
  const std::unique_ptr<ArtifactStore> store = OpenWriteBehindStore(path);
  NewArtifact bad = Row("clean", "bad");
  bad.input_keys = {"two\nlines"};
  store->WriteMessageArtifact(bad, Grid(100, 6));
  try {
    store->WriteMessageArtifact(Row("voronoi", "after"), Grid(100, 7));
    FAIL() << "the write after a failed one went ahead";
  } catch (const MapStepError& error) {
    EXPECT_EQ(error.step(), "clean");
  }
  store->FinishWrites();
  EXPECT_FALSE(store->HasArtifact(kMap, "after"));
  EXPECT_TRUE(OpenArtifactStore(path, StoreMode::kReadOnly)->ReadArtifactSummaries(kMap).empty());
}

// Closing waits for the pending write.
TEST(WriteBehindStoreTest, ClosingFinishesThePendingWrite) {
  testing::TempDir dir;
  const std::string path = dir.File("store.db");
  OpenWriteBehindStore(path)->WriteMessageArtifact(Row("import", "k1"), Grid(2 << 20, 8));
  EXPECT_EQ(StoredArtifact(path, "k1").payload_digest,
            Sha256Hex(Grid(2 << 20, 8).SerializeAsString()));
  EXPECT_FALSE(HasWriteAheadLog(path));
}

// A big shared message (a stage's result, kept for the next stage) is
// streamed by the thread from the message itself: the same bytes as a direct
// write, and the store's hold on it ends with the write, so a stage that
// takes its input over (cut) gets it once FinishWrites returns.
TEST(WriteBehindStoreTest, SharedBigMessageIsHeldUntilWrittenAndStoredAsADirectWrite) {
  testing::TempDir dir;
  for (const size_t cells : {size_t{100}, kWriteBehindMaxBytes + 1}) {
    const std::string key = "k" + std::to_string(cells);
    auto grid = std::make_shared<const proto::GridMap>(Grid(cells, 10));
    OpenArtifactStore(dir.File("direct.db"))->WriteMessageArtifact(Row("import", key), *grid);
    const std::unique_ptr<ArtifactStore> behind = OpenWriteBehindStore(dir.File("behind.db"));
    behind->WriteSharedMessageArtifact(Row("import", key), grid);
    EXPECT_EQ(behind->ReadHeadKey(kMap, "import"), key);
    EXPECT_TRUE(behind->HasArtifact(kMap, key));
    behind->WriteMessageArtifact(Row("clean", key + "c"), Grid(100, 11));  // waits for it
    EXPECT_EQ(grid.use_count(), 1) << cells;
    behind->FinishWrites();
    const ArtifactRecord direct = StoredArtifact(dir.File("direct.db"), key);
    const ArtifactRecord written = StoredArtifact(dir.File("behind.db"), key);
    EXPECT_EQ(written.payload_digest, direct.payload_digest) << cells;
    EXPECT_EQ(written.payload_digest, Sha256Hex(grid->SerializeAsString())) << cells;
    EXPECT_EQ(StoredArtifact(dir.File("behind.db"), key + "c").summary_line, "clean summary");
  }
}

// A shared message whose write fails is released too, and the error is
// thrown once, naming its stage.
TEST(WriteBehindStoreTest, SharedBigMessageWhoseWriteFailsIsReleased) {
  testing::TempDir dir;
  const std::string path = dir.File("store.db");
  auto grid = std::make_shared<const proto::GridMap>(Grid(kWriteBehindMaxBytes + 1, 12));
  const std::unique_ptr<ArtifactStore> store = OpenWriteBehindStore(path);
  NewArtifact bad = Row("voronoi", "bad");
  bad.input_keys = {"two\nlines"};  // refused by the store
  store->WriteSharedMessageArtifact(bad, grid);
  try {
    store->FinishWrites();
    ADD_FAILURE() << "the failed write went unreported";
  } catch (const MapStepError& error) {
    EXPECT_EQ(error.step(), "voronoi");
    EXPECT_NE(error.cause().find("line break"), std::string::npos) << error.cause();
  }
  EXPECT_EQ(grid.use_count(), 1);
  EXPECT_NO_THROW(store->FinishWrites());  // thrown once
  EXPECT_EQ(store->ReadHeadKey(kMap, "voronoi"), std::nullopt);
}

TEST(WriteBehindStoreTest, MemoryStoreWritesAtOnce) {
  const std::unique_ptr<ArtifactStore> store = OpenWriteBehindStore(":memory:");
  store->WriteMessageArtifact(Row("import", "k1"), Grid(100, 9));
  EXPECT_TRUE(store->ReadArtifact(kMap, "k1"));
}

}  // namespace
}  // namespace areagraph
