// Each map's history of versions (schema 4): written with its artifact in one
// transaction, kept by gc and merge, absent from older stores.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/error.h"
#include "store/artifact_store.h"
#include "tests/store/maintenance_helpers.h"
#include "tests/support/raw_sqlite.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::Artifact;
using testing::QueryColumn;
using Keys = std::vector<std::string>;

// A match artifact recorded as version `number` after `predecessor`.
NewArtifact Version(const std::string& map_name, const std::string& key,
                    const std::string& merge_key, const std::string& predecessor, int64_t number) {
  NewArtifact artifact = Artifact(map_name, "match", key, {merge_key}, key);
  artifact.version = VersionLink{predecessor, number};
  return artifact;
}

// "number:key<-predecessor" per version, oldest first, with "*" for the head
// and "!" for one no longer stored.
Keys History(ArtifactStore& store, const std::string& map_name) {
  Keys lines;
  for (const VersionRecord& version : store.ReadVersions(map_name)) {
    lines.push_back(std::to_string(version.number) + ":" + version.cache_key + "<-" +
                    version.predecessor_key + (version.is_head ? "*" : "") +
                    (version.stored ? "" : "!"));
  }
  return lines;
}

// Three versions of map "m", each from its own merge artifact.
void WriteThreeVersions(ArtifactStore& store) {
  for (int i = 1; i <= 3; ++i) {
    const std::string n = std::to_string(i);
    store.WriteArtifact(Artifact("m", "merge", "g" + n, {}, "graph " + n));
    store.WriteArtifact(
        Version("m", "v" + n, "g" + n, i == 1 ? "" : "v" + std::to_string(i - 1), i));
  }
}

TEST(VersionsTest, WrittenWithTheArtifactAndListedOldestFirst) {
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  WriteThreeVersions(*store);
  EXPECT_EQ(History(*store, "m"), (Keys{"1:v1<-", "2:v2<-v1", "3:v3<-v2*"}));
  const std::optional<VersionRecord> second = store->ReadVersion("m", "v2");
  ASSERT_TRUE(second);
  EXPECT_EQ(second->stage, "match");
  EXPECT_EQ(second->predecessor_key, "v1");
  EXPECT_EQ(second->number, 2);
  EXPECT_FALSE(second->created_at.empty());
  EXPECT_TRUE(second->stored);
  EXPECT_FALSE(second->is_head);
  EXPECT_FALSE(store->ReadVersion("m", "g2"));  // a merge artifact is no version
  EXPECT_FALSE(store->ReadVersion("other", "v2"));
  EXPECT_TRUE(store->ReadVersions("other").empty());
  // Writing a version again (recomputed with --force) keeps its first row,
  // and its place in the list; it becomes the head.
  store->WriteArtifact(Version("m", "v2", "g2", "v1", 2));
  EXPECT_EQ(History(*store, "m"), (Keys{"1:v1<-", "2:v2<-v1*", "3:v3<-v2"}));
}

TEST(VersionsTest, ARefusedVersionLeavesNoArtifact) {
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  EXPECT_THROW(store->WriteArtifact(Version("m", "v0", "g0", "", 0)), StoreError);
  EXPECT_FALSE(store->HasArtifact("m", "v0"));
  EXPECT_FALSE(store->ReadHeadKey("m", "match"));
  EXPECT_TRUE(store->ReadVersions("m").empty());
}

TEST(VersionsTest, GcDropsSupersededVersionsButKeepsTheirRows) {
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  WriteThreeVersions(*store);
  const MaintenanceCounts removed = store->CollectGarbage();
  // v1, v2 and the merge artifacts they were made from: no head reaches them.
  EXPECT_EQ(removed.artifacts, 4);
  EXPECT_EQ(testing::KeysOf(*store, "m"), (Keys{"g3", "v3"}));
  EXPECT_EQ(History(*store, "m"), (Keys{"1:v1<-!", "2:v2<-v1!", "3:v3<-v2*"}));
  EXPECT_TRUE(store->Verify({"import"}).empty());
  // The next version still follows the head.
  store->WriteArtifact(Artifact("m", "merge", "g4", {}, "graph 4"));
  store->WriteArtifact(Version("m", "v4", "g4", "v3", 4));
  EXPECT_EQ(History(*store, "m").back(), "4:v4<-v3*");
}

TEST(VersionsTest, MergeCopiesTheHistoryByMapAndKey) {
  testing::TempDir dir;
  {
    // b is written first, so a's heads are the later ones and win.
    std::unique_ptr<ArtifactStore> b = OpenArtifactStore(dir.File("b.db"));
    b->WriteArtifact(Artifact("other", "merge", "h1", {}, "other graph"));
    b->WriteArtifact(Version("other", "w1", "h1", "", 1));
    b->WriteArtifact(Artifact("m", "merge", "g1", {}, "graph 1"));
    b->WriteArtifact(Version("m", "v1", "g1", "", 1));  // both stores hold v1
    std::unique_ptr<ArtifactStore> a = OpenArtifactStore(dir.File("a.db"));
    WriteThreeVersions(*a);
  }
  std::unique_ptr<ArtifactStore> out = OpenArtifactStore(dir.File("out.db"));
  out->MergeFrom(dir.File("b.db"));
  out->MergeFrom(dir.File("a.db"));
  EXPECT_EQ(History(*out, "m"), (Keys{"1:v1<-", "2:v2<-v1", "3:v3<-v2*"}));
  EXPECT_EQ(History(*out, "other"), (Keys{"1:w1<-*"}));
  EXPECT_EQ(QueryColumn(dir.File("out.db"), "SELECT count(*) FROM versions"), Keys{"4"});
}

// A store of schema 3: schema 4 without the versions table.
void CreateVersion3Store(const std::string& path) {
  {
    std::unique_ptr<ArtifactStore> store = OpenArtifactStore(path);
    store->WriteArtifact(Artifact("m", "merge", "g1", {}, "graph 1"));
  }
  testing::RewriteAsSchema4(path);
  testing::ExecSql(path, "DROP TABLE versions; PRAGMA user_version = 3");
}

TEST(VersionsTest, ReadOnlyOpenOfSchema3HasNoHistory) {
  testing::TempDir dir;
  const std::string path = dir.File("v3.db");
  CreateVersion3Store(path);
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(path, StoreMode::kReadOnly);
  EXPECT_TRUE(store->ReadVersions("m").empty());
  EXPECT_FALSE(store->ReadVersion("m", "g1"));
  EXPECT_EQ(store->ReadHeadKey("m", "merge"), "g1");
  store.reset();
  EXPECT_EQ(QueryColumn(path, "PRAGMA user_version"), Keys{"3"});
}

TEST(VersionsTest, ReadWriteOpenUpgradesSchema3AndMergeReadsIt) {
  testing::TempDir dir;
  const std::string old_path = dir.File("v3.db");
  CreateVersion3Store(old_path);
  // Merging a schema-3 store copies its artifacts and has no history to copy.
  std::unique_ptr<ArtifactStore> out = OpenArtifactStore(dir.File("out.db"));
  EXPECT_EQ(out->MergeFrom(old_path).artifacts, 1);
  EXPECT_TRUE(out->ReadVersions("m").empty());
  EXPECT_EQ(QueryColumn(old_path, "PRAGMA user_version"), Keys{"3"});

  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(old_path);
  EXPECT_EQ(QueryColumn(old_path, "PRAGMA user_version"),
            Keys{std::to_string(kStoreSchemaVersion)});
  store->WriteArtifact(Version("m", "v1", "g1", "", 1));
  EXPECT_EQ(History(*store, "m"), (Keys{"1:v1<-*"}));
}

TEST(VersionsTest, FailedUpgradeLeavesSchema3Unchanged) {
  testing::TempDir dir;
  const std::string path = dir.File("v3.db");
  CreateVersion3Store(path);
  testing::ExecSql(path, "CREATE TABLE versions (note TEXT)");
  EXPECT_THROW(OpenArtifactStore(path), StoreError);
  EXPECT_EQ(QueryColumn(path, "PRAGMA user_version"), Keys{"3"});
  EXPECT_EQ(OpenArtifactStore(path, StoreMode::kReadOnly)->ReadHeadKey("m", "merge"), "g1");
}

}  // namespace
}  // namespace areagraph
