#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "common/error.h"
#include "store/artifact_store.h"
#include "store/digest.h"
#include "tests/support/raw_sqlite.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::MakeArtifact;

// Payload with every byte value, NULs included.
std::string BinaryPayload(int size, int seed) {
  std::string payload(size, '\0');
  for (int i = 0; i < size; ++i) payload[i] = static_cast<char>((i * 7 + seed) & 0xff);
  return payload;
}

void ExpectMatches(const ArtifactRecord& read, const NewArtifact& written) {
  EXPECT_EQ(read.map_name, written.map_name);
  EXPECT_EQ(read.stage, written.stage);
  EXPECT_EQ(read.cache_key, written.cache_key);
  EXPECT_EQ(read.input_keys, written.input_keys);
  EXPECT_EQ(read.options_text, written.options_text);
  EXPECT_EQ(read.stage_version, written.stage_version);
  EXPECT_EQ(read.proto_type, written.proto_type);
  EXPECT_EQ(read.payload, written.payload);
  EXPECT_EQ(read.payload_bytes, static_cast<int64_t>(written.payload.size()));
  EXPECT_EQ(read.payload_digest, Sha256Hex(written.payload));
  EXPECT_DOUBLE_EQ(read.elapsed_ms, written.elapsed_ms);
  EXPECT_TRUE(
      std::regex_match(read.created_at, std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}Z)")))
      << read.created_at;
}

TEST(SqliteArtifactStoreTest, RoundTripInMemory) {
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  NewArtifact written = MakeArtifact("lab_a", "voronoi", "key1", BinaryPayload(5000, 1));
  written.source_path = "/maps/lab_a.png";
  written.source_digest = "d1";
  store->WriteArtifact(written);

  const std::optional<ArtifactRecord> by_key = store->ReadArtifact("lab_a", "key1");
  ASSERT_TRUE(by_key);
  ExpectMatches(*by_key, written);
  EXPECT_TRUE(by_key->is_head);
  const std::optional<ArtifactRecord> head = store->ReadHead("lab_a", "voronoi");
  ASSERT_TRUE(head);
  ExpectMatches(*head, written);

  const std::optional<MapRecord> map = store->ReadMap("lab_a");
  ASSERT_TRUE(map);
  EXPECT_EQ(map->name, "lab_a");
  EXPECT_EQ(map->source_path, "/maps/lab_a.png");
  EXPECT_EQ(map->source_digest, "d1");
  EXPECT_GT(map->id, 0);
}

TEST(SqliteArtifactStoreTest, InMemoryStoresArePrivate) {
  std::unique_ptr<ArtifactStore> first = OpenArtifactStore(":memory:");
  first->WriteArtifact(MakeArtifact("m", "clean", "k", "x"));
  std::unique_ptr<ArtifactStore> second = OpenArtifactStore(":memory:");
  EXPECT_TRUE(second->ReadAllMaps().empty());
}

TEST(SqliteArtifactStoreTest, RoundTripThroughFileAfterReopen) {
  testing::TempDir dir;
  const std::string path = dir.File("store.db");
  const NewArtifact written = MakeArtifact("lab_a", "clean", "key1", BinaryPayload(300000, 2));
  const NewArtifact empty_payload = MakeArtifact("lab_b", "import", "key2", "");
  NewArtifact no_inputs = MakeArtifact("lab_b", "clean", "key3", "abc");
  no_inputs.input_keys.clear();
  {
    std::unique_ptr<ArtifactStore> store = OpenArtifactStore(path);
    store->WriteArtifact(written);
    store->WriteArtifact(empty_payload);
    store->WriteArtifact(no_inputs);
  }
  for (StoreMode mode : {StoreMode::kReadWrite, StoreMode::kReadOnly}) {
    std::unique_ptr<ArtifactStore> store = OpenArtifactStore(path, mode);
    std::optional<ArtifactRecord> read = store->ReadArtifact("lab_a", "key1");
    ASSERT_TRUE(read);
    ExpectMatches(*read, written);
    read = store->ReadHead("lab_b", "import");
    ASSERT_TRUE(read);
    ExpectMatches(*read, empty_payload);
    read = store->ReadHead("lab_b", "clean");
    ASSERT_TRUE(read);
    ExpectMatches(*read, no_inputs);
    const std::vector<MapRecord> maps = store->ReadAllMaps();
    ASSERT_EQ(maps.size(), 2u);
    EXPECT_EQ(maps[0].name, "lab_a");
    EXPECT_EQ(maps[1].name, "lab_b");
  }
}

TEST(SqliteArtifactStoreTest, FileStoreUsesWalForeignKeysAndSchemaVersion) {
  testing::TempDir dir;
  const std::string path = dir.File("store.db");
  OpenArtifactStore(path)->WriteArtifact(MakeArtifact("m", "clean", "k", "x"));
  EXPECT_EQ(testing::QueryColumn(path, "PRAGMA journal_mode"), std::vector<std::string>{"wal"});
  EXPECT_EQ(testing::QueryColumn(path, "PRAGMA user_version"),
            std::vector<std::string>{std::to_string(kStoreSchemaVersion)});
  // ON DELETE CASCADE: deleting a map removes its artifacts and heads.
  testing::ExecSql(path, "PRAGMA foreign_keys = ON; DELETE FROM maps WHERE name = 'm'");
  EXPECT_EQ(testing::QueryColumn(path, "SELECT count(*) FROM artifacts"),
            std::vector<std::string>{"0"});
  EXPECT_EQ(testing::QueryColumn(path, "SELECT count(*) FROM heads"),
            std::vector<std::string>{"0"});
}

TEST(SqliteArtifactStoreTest, MissingThingsReadAsNullopt) {
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  EXPECT_FALSE(store->ReadMap("nope"));
  EXPECT_FALSE(store->ReadHead("nope", "clean"));
  EXPECT_FALSE(store->ReadArtifact("nope", "k"));
  EXPECT_TRUE(store->ReadArtifactSummaries("nope").empty());
  store->WriteArtifact(MakeArtifact("m", "clean", "k", "x"));
  EXPECT_FALSE(store->ReadHead("m", "voronoi"));
  EXPECT_FALSE(store->ReadArtifact("m", "other"));
  EXPECT_FALSE(store->ReadArtifact("other_map", "k"));  // keys are per map
}

TEST(SqliteArtifactStoreTest, NewArtifactReplacesHeadAndKeepsOldOne) {
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  store->WriteArtifact(MakeArtifact("m", "clean", "k1", "one"));
  store->WriteArtifact(MakeArtifact("m", "clean", "k2", "two"));
  const std::optional<ArtifactRecord> head = store->ReadHead("m", "clean");
  ASSERT_TRUE(head);
  EXPECT_EQ(head->cache_key, "k2");
  EXPECT_EQ(head->payload, "two");
  const std::optional<ArtifactRecord> old = store->ReadArtifact("m", "k1");
  ASSERT_TRUE(old);
  EXPECT_EQ(old->payload, "one");
  EXPECT_FALSE(old->is_head);
}

TEST(SqliteArtifactStoreTest, HeadsAreSeparatePerStageAndMap) {
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  store->WriteArtifact(MakeArtifact("a", "clean", "k1", "a-clean"));
  store->WriteArtifact(MakeArtifact("a", "voronoi", "k2", "a-voronoi"));
  store->WriteArtifact(MakeArtifact("b", "clean", "k1", "b-clean"));  // same key, other map
  EXPECT_EQ(store->ReadHead("a", "clean")->payload, "a-clean");
  EXPECT_EQ(store->ReadHead("a", "voronoi")->payload, "a-voronoi");
  EXPECT_EQ(store->ReadHead("b", "clean")->payload, "b-clean");
  EXPECT_EQ(store->ReadArtifact("a", "k1")->payload, "a-clean");
  EXPECT_EQ(store->ReadArtifact("b", "k1")->payload, "b-clean");
}

TEST(SqliteArtifactStoreTest, RewritingAKeyReplacesTheRowAndStaysHead) {
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  store->WriteArtifact(MakeArtifact("m", "clean", "k1", "first"));
  store->WriteArtifact(MakeArtifact("m", "clean", "k2", "other"));
  NewArtifact again = MakeArtifact("m", "clean", "k1", "second");
  again.elapsed_ms = 99;
  store->WriteArtifact(again);
  const std::vector<ArtifactRecord> summaries = store->ReadArtifactSummaries("m");
  ASSERT_EQ(summaries.size(), 2u);
  const std::optional<ArtifactRecord> head = store->ReadHead("m", "clean");
  ASSERT_TRUE(head);
  ExpectMatches(*head, again);
}

TEST(SqliteArtifactStoreTest, UpdateHeadPointsBackAtAnOlderArtifact) {
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  store->WriteArtifact(MakeArtifact("m", "clean", "k1", "one"));
  store->WriteArtifact(MakeArtifact("m", "clean", "k2", "two"));
  store->WriteArtifact(MakeArtifact("m", "voronoi", "k3", "three"));
  store->UpdateHead("m", "k1");
  EXPECT_EQ(store->ReadHead("m", "clean")->cache_key, "k1");
  EXPECT_FALSE(store->ReadArtifact("m", "k2")->is_head);
  EXPECT_TRUE(store->ReadArtifact("m", "k1")->is_head);
  EXPECT_EQ(store->ReadHead("m", "voronoi")->cache_key, "k3");  // other stage untouched
  store->UpdateHead("m", "k1");                                 // idempotent
  EXPECT_EQ(store->ReadHead("m", "clean")->cache_key, "k1");
}

TEST(SqliteArtifactStoreTest, UpdateHeadOfUnknownKeyThrows) {
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  store->WriteArtifact(MakeArtifact("m", "clean", "k1", "one"));
  EXPECT_THROW(store->UpdateHead("m", "missing"), StoreError);
  EXPECT_THROW(store->UpdateHead("other", "k1"), StoreError);
  EXPECT_EQ(store->ReadHead("m", "clean")->cache_key, "k1");
}

TEST(SqliteArtifactStoreTest, SummariesListOldestFirstWithoutPayloads) {
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  store->WriteArtifact(MakeArtifact("m", "import", "k1", std::string(10, 'a')));
  store->WriteArtifact(MakeArtifact("m", "clean", "k2", std::string(2000, 'b')));
  store->WriteArtifact(MakeArtifact("m", "clean", "k3", std::string(30, 'c')));
  store->WriteArtifact(MakeArtifact("other", "clean", "k4", "d"));
  const std::vector<ArtifactRecord> summaries = store->ReadArtifactSummaries("m");
  ASSERT_EQ(summaries.size(), 3u);
  const std::vector<std::string> keys = {"k1", "k2", "k3"};
  const std::vector<int64_t> sizes = {10, 2000, 30};
  const std::vector<bool> heads = {true, false, true};
  for (size_t i = 0; i < summaries.size(); ++i) {
    EXPECT_EQ(summaries[i].cache_key, keys[i]);
    EXPECT_EQ(summaries[i].map_name, "m");
    EXPECT_TRUE(summaries[i].payload.empty());
    EXPECT_EQ(summaries[i].payload_bytes, sizes[i]);
    EXPECT_EQ(summaries[i].is_head, heads[i]) << keys[i];
    EXPECT_EQ(summaries[i].payload_digest, Sha256Hex(std::string(sizes[i], 'a' + i)));
    EXPECT_EQ(summaries[i].input_keys.size(), 2u);
    if (i > 0) {
      EXPECT_LE(summaries[i - 1].created_at, summaries[i].created_at);
    }
  }
}

TEST(SqliteArtifactStoreTest, MapSourceIsKeptUnlessGiven) {
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  NewArtifact imported = MakeArtifact("m", "import", "k1", "grid");
  imported.source_path = "/a.png";
  imported.source_digest = "aaa";
  store->WriteArtifact(imported);
  store->WriteArtifact(MakeArtifact("m", "clean", "k2", "cleaned"));  // no source
  EXPECT_EQ(store->ReadMap("m")->source_path, "/a.png");
  EXPECT_EQ(store->ReadMap("m")->source_digest, "aaa");
  imported = MakeArtifact("m", "import", "k3", "grid2");
  imported.source_path = "/b.png";
  imported.source_digest = "bbb";
  store->WriteArtifact(imported);
  EXPECT_EQ(store->ReadMap("m")->source_path, "/b.png");
  EXPECT_EQ(store->ReadMap("m")->source_digest, "bbb");
  // A map first seen without a source gets empty strings.
  store->WriteArtifact(MakeArtifact("n", "clean", "k4", "x"));
  EXPECT_EQ(store->ReadMap("n")->source_path, "");
  EXPECT_EQ(store->ReadAllMaps().size(), 2u);
}

TEST(SqliteArtifactStoreTest, ReadOnlyStoreRefusesWrites) {
  testing::TempDir dir;
  const std::string path = dir.File("store.db");
  OpenArtifactStore(path)->WriteArtifact(MakeArtifact("m", "clean", "k1", "x"));
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(path, StoreMode::kReadOnly);
  EXPECT_EQ(store->ReadHead("m", "clean")->payload, "x");
  try {
    store->WriteArtifact(MakeArtifact("m", "clean", "k2", "y"));
    FAIL() << "expected StoreError";
  } catch (const StoreError& error) {
    EXPECT_NE(std::string(error.what()).find("read-only"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
  }
  EXPECT_THROW(store->UpdateHead("m", "k1"), StoreError);
  EXPECT_FALSE(store->ReadArtifact("m", "k2"));
}

// A failure in the middle of a write (here injected with a trigger on the
// heads table) must roll back the map and artifact rows written before it,
// and leave the store usable.
TEST(SqliteArtifactStoreTest, FailedWriteRollsBackEverything) {
  testing::TempDir dir;
  const std::string path = dir.File("store.db");
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(path);
  NewArtifact first = MakeArtifact("m", "clean", "k1", "one");
  first.source_path = "/old.png";
  store->WriteArtifact(first);
  testing::ExecSql(path,
                   "CREATE TRIGGER fail_insert BEFORE INSERT ON heads "
                   "BEGIN SELECT RAISE(ABORT, 'injected failure'); END;"
                   "CREATE TRIGGER fail_update BEFORE UPDATE ON heads "
                   "BEGIN SELECT RAISE(ABORT, 'injected failure'); END;");
  NewArtifact second = MakeArtifact("m", "clean", "k2", "two");
  second.source_path = "/new.png";
  EXPECT_THROW(store->WriteArtifact(second), StoreError);
  EXPECT_THROW(store->WriteArtifact(MakeArtifact("n", "clean", "k3", "three")), StoreError);
  EXPECT_THROW(store->UpdateHead("m", "k1"), StoreError);

  EXPECT_FALSE(store->ReadArtifact("m", "k2"));
  EXPECT_FALSE(store->ReadMap("n"));
  EXPECT_EQ(store->ReadMap("m")->source_path, "/old.png");
  EXPECT_EQ(store->ReadHead("m", "clean")->cache_key, "k1");

  testing::ExecSql(path, "DROP TRIGGER fail_insert; DROP TRIGGER fail_update;");
  store->WriteArtifact(second);  // no transaction was left open
  EXPECT_EQ(store->ReadHead("m", "clean")->cache_key, "k2");
  EXPECT_EQ(store->ReadMap("m")->source_path, "/new.png");
}

}  // namespace
}  // namespace areagraph
