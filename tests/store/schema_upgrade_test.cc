// Opening a store written by schema version 1 (before failures existed).
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

TEST(SchemaUpgradeTest, ReadWriteOpenUpgradesVersion1) {
  testing::TempDir dir;
  const std::string path = dir.File("v1.db");
  testing::CreateVersion1Store(path);
  ASSERT_EQ(Tables(path), (std::vector<std::string>{"artifacts", "heads", "maps"}));

  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(path);
  EXPECT_EQ(QueryColumn(path, "PRAGMA user_version"),
            std::vector<std::string>{std::to_string(kStoreSchemaVersion)});
  EXPECT_EQ(Tables(path), (std::vector<std::string>{"artifacts", "failures", "heads", "maps"}));
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
