// Opening a store written by schema version 1 (before failures existed) or
// 2 (failures, no summary column, no versions table). Schema 3 is in
// versions_test.cc.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "common/error.h"
#include "store/artifact_store.h"
#include "tests/store/maintenance_helpers.h"
#include "tests/support/raw_sqlite.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::QueryColumn;

std::vector<std::string> Tables(const std::string& path) {
  return QueryColumn(path, "SELECT name FROM sqlite_master WHERE type = 'table' ORDER BY name");
}

void ExpectVersion1DataIntact(ArtifactStore& store) {
  const std::optional<MapRecord> map = store.ReadMap("old_map");
  ASSERT_TRUE(map);
  EXPECT_EQ(map->source_path, "old.png");
  const std::optional<ArtifactRecord> clean = store.ReadHead("old_map", "clean");
  ASSERT_TRUE(clean);
  EXPECT_EQ(clean->cache_key, "v1-clean");
  EXPECT_EQ(clean->payload, testing::ProtoBytes("v1 clean"));
  EXPECT_EQ(clean->input_keys, std::vector<std::string>{"v1-import"});
  EXPECT_EQ(store.ReadHeadKey("old_map", "import"), "v1-import");
}

// The store at `path` has this build's schema version and every table.
void ExpectCurrentSchema(const std::string& path) {
  EXPECT_EQ(QueryColumn(path, "PRAGMA user_version"),
            std::vector<std::string>{std::to_string(kStoreSchemaVersion)});
  EXPECT_EQ(Tables(path),
            (std::vector<std::string>{"artifacts", "failures", "heads", "maps", "versions"}));
}

TEST(SchemaUpgradeTest, ReadWriteOpenUpgradesVersion1) {
  testing::TempDir dir;
  const std::string path = dir.File("v1.db");
  testing::CreateVersion1Store(path);
  ASSERT_EQ(Tables(path), (std::vector<std::string>{"artifacts", "heads", "maps"}));

  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(path);
  ExpectCurrentSchema(path);
  ExpectVersion1DataIntact(*store);
  EXPECT_TRUE(store->ReadFailures().empty());
  FailureRecord failure;
  failure.map_name = "old_map";
  failure.stage = "cut";
  failure.message = "boom";
  store->RecordFailure(failure);
  EXPECT_EQ(store->ReadFailures().size(), 1u);
  EXPECT_TRUE(store->Verify({"import"}).empty());
  store.reset();
  // Opening again changes nothing.
  OpenArtifactStore(path);
  EXPECT_EQ(QueryColumn(path, "PRAGMA user_version"),
            std::vector<std::string>{std::to_string(kStoreSchemaVersion)});
}

// Schema 3: summary lines. Rows written before it read back with an empty
// one; new rows keep theirs, in full reads and in summaries.
TEST(SchemaUpgradeTest, UpgradeAddsSummaryLines) {
  testing::TempDir dir;
  const std::string path = dir.File("v1.db");
  testing::CreateVersion1Store(path);
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(path);
  const std::vector<std::string> columns = QueryColumn(path, "PRAGMA table_info(artifacts)", 1);
  EXPECT_NE(std::find(columns.begin(), columns.end(), "summary"), columns.end());
  EXPECT_EQ(store->ReadHead("old_map", "clean")->summary_line, "");
  NewArtifact artifact = testing::Artifact("old_map", "voronoi", "v3-voronoi", {"v1-clean"}, "d");
  artifact.summary_line = "3 sites, 1 vertices, 0 edges";
  store->WriteArtifact(artifact);
  EXPECT_EQ(store->ReadHead("old_map", "voronoi")->summary_line, artifact.summary_line);
  EXPECT_EQ(store->ReadArtifactSummary("old_map", "v3-voronoi")->summary_line,
            artifact.summary_line);
  EXPECT_FALSE(store->ReadArtifactSummary("old_map", "no-such-key"));
}

// Schema 2 as it was written: version 1 plus the failures table.
void CreateVersion2Store(const std::string& path) {
  testing::CreateVersion1Store(path);
  testing::ExecSql(path,
                   "CREATE TABLE failures (map_name TEXT PRIMARY KEY, stage TEXT NOT NULL, "
                   "message TEXT NOT NULL, source_path TEXT NOT NULL DEFAULT '', "
                   "failed_at TEXT NOT NULL);"
                   "INSERT INTO failures VALUES ('old_map', 'cut', 'boom', 'old.png', "
                   "'2025-01-02T00:00:00.000Z');"
                   "PRAGMA user_version = 2;");
}

TEST(SchemaUpgradeTest, ReadWriteOpenUpgradesVersion2KeepingItsFailures) {
  testing::TempDir dir;
  const std::string path = dir.File("v2.db");
  CreateVersion2Store(path);
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(path);
  ExpectCurrentSchema(path);
  ExpectVersion1DataIntact(*store);
  const std::vector<FailureRecord> failures = store->ReadFailures();
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_EQ(failures[0].message, "boom");
  EXPECT_EQ(store->ReadHead("old_map", "clean")->summary_line, "");
  // The new tables work: a match artifact becomes the map's first version.
  NewArtifact match = testing::Artifact("old_map", "match", "v4-match", {"v1-clean"}, "graph");
  match.version = VersionLink{"", 1};
  store->WriteArtifact(match);
  const std::vector<VersionRecord> history = store->ReadVersions("old_map");
  ASSERT_EQ(history.size(), 1u);
  EXPECT_EQ(history[0].cache_key, "v4-match");
  EXPECT_EQ(history[0].number, 1);
}

TEST(SchemaUpgradeTest, ReadOnlyOpenReadsVersion1AsItIs) {
  testing::TempDir dir;
  const std::string path = dir.File("v1.db");
  testing::CreateVersion1Store(path);
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(path, StoreMode::kReadOnly);
  ExpectVersion1DataIntact(*store);
  EXPECT_TRUE(store->ReadFailures().empty());
  EXPECT_TRUE(store->Verify({"import"}).empty());
  store->ClearFailure("old_map");  // nothing to clear
  EXPECT_THROW(store->RecordFailure(FailureRecord{"old_map", "cut", "x", "", ""}), StoreError);
  store.reset();
  EXPECT_EQ(QueryColumn(path, "PRAGMA user_version"), std::vector<std::string>{"1"});
  EXPECT_EQ(Tables(path), (std::vector<std::string>{"artifacts", "heads", "maps"}));
}

TEST(SchemaUpgradeTest, ReaderKeepsWorkingWhileAnotherConnectionUpgrades) {
  testing::TempDir dir;
  const std::string path = dir.File("v1.db");
  testing::CreateVersion1Store(path);
  std::unique_ptr<ArtifactStore> reader = OpenArtifactStore(path, StoreMode::kReadOnly);
  std::unique_ptr<ArtifactStore> writer = OpenArtifactStore(path);  // upgrades
  ExpectVersion1DataIntact(*reader);
  EXPECT_TRUE(reader->ReadFailures().empty());  // it opened a version-1 store
  writer->WriteArtifact(testing::Artifact("new_map", "import", "k", {"file"}));
  EXPECT_EQ(reader->ReadHeadKey("new_map", "import"), "k");
}

TEST(SchemaUpgradeTest, FailedUpgradeLeavesVersion1Unchanged) {
  testing::TempDir dir;
  const std::string path = dir.File("v1.db");
  testing::CreateVersion1Store(path);
  // Something else already took the name of the new table.
  testing::ExecSql(path, "CREATE TABLE failures (note TEXT); INSERT INTO failures VALUES ('mine')");
  try {
    OpenArtifactStore(path);
    ADD_FAILURE() << "the upgrade should have failed";
  } catch (const StoreError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find("failures"), std::string::npos) << message;
  }
  EXPECT_EQ(QueryColumn(path, "PRAGMA user_version"), std::vector<std::string>{"1"});
  EXPECT_EQ(QueryColumn(path, "SELECT note FROM failures"), std::vector<std::string>{"mine"});
  // Still readable as the version-1 store it is.
  ExpectVersion1DataIntact(*OpenArtifactStore(path, StoreMode::kReadOnly));
}

}  // namespace
}  // namespace areagraph
