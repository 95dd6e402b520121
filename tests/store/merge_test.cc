// ArtifactStore::MergeFrom: shards combined, conflicts resolved by time.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "common/error.h"
#include "store/artifact_store.h"
#include "tests/store/maintenance_helpers.h"
#include "tests/support/raw_sqlite.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::Artifact;
using testing::KeysOf;
using testing::MapNames;
using testing::ReadFile;
using testing::SetCreatedAt;
using Names = std::vector<std::string>;

std::string MergeError(ArtifactStore& store, const std::string& path) {
  try {
    store.MergeFrom(path);
  } catch (const StoreError& error) {
    return error.what();
  }
  return "";
}

NewArtifact Import(const std::string& map_name, const std::string& key, const std::string& source) {
  NewArtifact artifact = Artifact(map_name, "import", key, {"digest-" + source}, key);
  artifact.source_path = source;
  artifact.source_digest = "digest-" + source;
  return artifact;
}

FailureRecord Failure(const std::string& map_name, const std::string& stage) {
  return FailureRecord{map_name, stage, stage + " failed", map_name + ".png", ""};
}

Names FailedMaps(ArtifactStore& store) {
  Names names;
  for (const FailureRecord& failure : store.ReadFailures()) {
    names.push_back(failure.map_name + ":" + failure.stage);
  }
  return names;
}

class MergeTest : public ::testing::Test {
 protected:
  std::string Path(const std::string& name) const { return dir_.File(name); }
  testing::TempDir dir_;
};

TEST_F(MergeTest, DisjointStoresAreCopiedWithEverything) {
  {
    std::unique_ptr<ArtifactStore> a = OpenArtifactStore(Path("a.db"));
    a->WriteArtifact(Import("lab_a", "ia", "a.png"));
    a->WriteArtifact(Artifact("lab_a", "clean", "ca", {"ia"}, "clean a"));
    a->RecordFailure(Failure("broken", "import"));
    OpenArtifactStore(Path("b.db"))->WriteArtifact(Import("lab_b", "ib", "b.png"));
  }
  const std::string a_before = ReadFile(Path("a.db"));
  const std::vector<ArtifactRecord> a_artifacts =
      OpenArtifactStore(Path("a.db"), StoreMode::kReadOnly)->ReadArtifactSummaries("lab_a");

  std::unique_ptr<ArtifactStore> out = OpenArtifactStore(":memory:");
  const MaintenanceCounts from_a = out->MergeFrom(Path("a.db"));
  EXPECT_EQ(from_a.maps, 1);
  EXPECT_EQ(from_a.artifacts, 2);
  EXPECT_EQ(from_a.payload_bytes, static_cast<int64_t>(testing::ProtoBytes("ia").size() +
                                                       testing::ProtoBytes("clean a").size()));
  EXPECT_EQ(from_a.failures, 1);
  const MaintenanceCounts from_b = out->MergeFrom(Path("b.db"));
  EXPECT_EQ(from_b.maps, 1);
  EXPECT_EQ(from_b.artifacts, 1);
  EXPECT_EQ(from_b.failures, 0);

  EXPECT_EQ(MapNames(*out), (Names{"lab_a", "lab_b"}));
  EXPECT_EQ(out->ReadMap("lab_a")->source_path, "a.png");
  EXPECT_EQ(out->ReadMap("lab_b")->source_digest, "digest-b.png");
  EXPECT_EQ(out->ReadHead("lab_a", "clean")->payload, testing::ProtoBytes("clean a"));
  EXPECT_EQ(out->ReadHead("lab_a", "clean")->input_keys, Names{"ia"});
  EXPECT_EQ(out->ReadHeadKey("lab_b", "import"), "ib");
  const std::vector<ArtifactRecord> copied = out->ReadArtifactSummaries("lab_a");
  ASSERT_EQ(copied.size(), a_artifacts.size());
  for (size_t i = 0; i < copied.size(); ++i) {
    EXPECT_EQ(copied[i].created_at, a_artifacts[i].created_at);  // kept, not "now"
  }
  EXPECT_EQ(FailedMaps(*out), Names{"broken:import"});
  EXPECT_TRUE(out->Verify({"import"}).empty());
  EXPECT_EQ(ReadFile(Path("a.db")), a_before);  // the source is only read

  // Merging again adds nothing.
  const MaintenanceCounts again = out->MergeFrom(Path("a.db"));
  EXPECT_EQ(again.maps + again.artifacts + again.payload_bytes + again.failures, 0);
}

TEST_F(MergeTest, ConflictingHeadGoesToTheLaterArtifact) {
  const std::string main_path = Path("main.db"), other_path = Path("other.db");
  {
    std::unique_ptr<ArtifactStore> main_store = OpenArtifactStore(main_path);
    main_store->WriteArtifact(Import("m", "i-main", "main.png"));
    main_store->WriteArtifact(Artifact("m", "clean", "c-main", {"i-main"}));
    main_store->WriteArtifact(Artifact("m", "cut", "u-main", {"c-main"}));
    std::unique_ptr<ArtifactStore> other = OpenArtifactStore(other_path);
    other->WriteArtifact(Import("m", "i-other", "other.png"));
    other->WriteArtifact(Artifact("m", "clean", "c-other", {"i-other"}));
    other->WriteArtifact(Artifact("m", "cut", "u-other", {"c-other"}));
  }
  SetCreatedAt(main_path, "i-main", "2026-01-01T00:00:00.000Z");
  SetCreatedAt(other_path, "i-other", "2026-02-01T00:00:00.000Z");  // newer import
  SetCreatedAt(main_path, "c-main", "2026-03-01T00:00:00.000Z");    // newer clean
  SetCreatedAt(other_path, "c-other", "2026-02-01T00:00:00.000Z");
  SetCreatedAt(main_path, "u-main", "2026-04-01T00:00:00.000Z");  // a tie keeps main's
  SetCreatedAt(other_path, "u-other", "2026-04-01T00:00:00.000Z");

  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(main_path);
  const MaintenanceCounts added = store->MergeFrom(other_path);
  EXPECT_EQ(added.maps, 0);
  EXPECT_EQ(added.artifacts, 3);
  EXPECT_EQ(store->ReadHeadKey("m", "import"), "i-other");
  EXPECT_EQ(store->ReadMap("m")->source_path, "other.png");  // follows the import head
  EXPECT_EQ(store->ReadMap("m")->source_digest, "digest-other.png");
  EXPECT_EQ(store->ReadHeadKey("m", "clean"), "c-main");
  EXPECT_EQ(store->ReadHeadKey("m", "cut"), "u-main");
  EXPECT_EQ(KeysOf(*store, "m"),
            (Names{"c-main", "c-other", "i-main", "i-other", "u-main", "u-other"}));
  EXPECT_TRUE(store->Verify({"import"}).empty());
}

TEST_F(MergeTest, ArtifactBothStoresHoldIsKeptAsItIs) {
  const std::string main_path = Path("main.db"), other_path = Path("other.db");
  OpenArtifactStore(main_path)->WriteArtifact(Artifact("m", "clean", "same", {"i"}));
  OpenArtifactStore(other_path)->WriteArtifact(Artifact("m", "clean", "same", {"i"}));
  SetCreatedAt(main_path, "same", "2026-01-01T00:00:00.000Z");
  SetCreatedAt(other_path, "same", "2026-06-01T00:00:00.000Z");
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(main_path);
  const MaintenanceCounts added = store->MergeFrom(other_path);
  EXPECT_EQ(added.artifacts, 0);
  EXPECT_EQ(added.payload_bytes, 0);
  EXPECT_EQ(store->ReadHead("m", "clean")->created_at, "2026-01-01T00:00:00.000Z");
}

TEST_F(MergeTest, LaterFailureWinsAndNewerHeadsOutdateFailures) {
  const std::string main_path = Path("main.db"), other_path = Path("other.db");
  {
    std::unique_ptr<ArtifactStore> main_store = OpenArtifactStore(main_path);
    main_store->RecordFailure(Failure("f1", "cut"));
    main_store->RecordFailure(Failure("f2", "cut"));
    main_store->WriteArtifact(Artifact("fixed", "import", "fixed-old", {"file"}));
    main_store->RecordFailure(Failure("fixed", "clean"));
    std::unique_ptr<ArtifactStore> other = OpenArtifactStore(other_path);
    other->RecordFailure(Failure("f1", "voronoi"));
    other->RecordFailure(Failure("f2", "merge"));
    other->WriteArtifact(Artifact("fixed", "import", "fixed-new", {"file"}));
    other->WriteArtifact(Artifact("stale", "import", "stale-k", {"file"}));
    other->RecordFailure(Failure("stale", "clean"));
    other->RecordFailure(Failure("new", "import"));
  }
  testing::SetFailedAt(main_path, "f1", "2026-01-01T00:00:00.000Z");
  testing::SetFailedAt(other_path, "f1", "2026-02-01T00:00:00.000Z");  // later: wins
  testing::SetFailedAt(main_path, "f2", "2026-05-01T00:00:00.000Z");   // later: stays
  testing::SetFailedAt(other_path, "f2", "2026-04-01T00:00:00.000Z");
  SetCreatedAt(main_path, "fixed-old", "2026-01-01T00:00:00.000Z");
  testing::SetFailedAt(main_path, "fixed", "2026-01-02T00:00:00.000Z");
  SetCreatedAt(other_path, "fixed-new", "2026-03-01T00:00:00.000Z");  // outdates the failure
  testing::SetFailedAt(other_path, "stale", "2026-01-01T00:00:00.000Z");
  SetCreatedAt(other_path, "stale-k", "2026-02-01T00:00:00.000Z");  // stale in its own store
  testing::SetFailedAt(other_path, "new", "2026-01-01T00:00:00.000Z");

  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(main_path);
  const MaintenanceCounts added = store->MergeFrom(other_path);
  EXPECT_EQ(added.failures, 2);  // f1 and new
  EXPECT_EQ(FailedMaps(*store), (Names{"f1:voronoi", "f2:cut", "new:import"}));
  EXPECT_EQ(store->ReadHeadKey("fixed", "import"), "fixed-new");
}

TEST_F(MergeTest, NewerSchemaIsRefusedAndNothingChanges) {
  const std::string main_path = Path("main.db"), newer = Path("newer.db");
  OpenArtifactStore(main_path)->WriteArtifact(Artifact("m", "clean", "k", {"i"}));
  OpenArtifactStore(newer)->WriteArtifact(Artifact("n", "clean", "k2", {"i"}));
  testing::ExecSql(newer, "PRAGMA user_version = 99");
  const std::string newer_before = ReadFile(newer);
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(main_path);
  EXPECT_EQ(MergeError(*store, newer),
            "store '" + newer + "' has schema version 99, newer than this build's " +
                std::to_string(kStoreSchemaVersion) + "; upgrade areagraph");
  EXPECT_EQ(MapNames(*store), Names{"m"});
  EXPECT_EQ(ReadFile(newer), newer_before);
}

TEST_F(MergeTest, MergingAStoreIntoItselfIsRefused) {
  const std::string path = Path("store.db");
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(path);
  store->WriteArtifact(Artifact("m", "clean", "k", {"i"}));
  std::filesystem::create_directory(Path("sub"));
  std::filesystem::create_symlink(path, Path("link.db"));
  for (const std::string& same : {path, Path("sub/../store.db"), Path("link.db")}) {
    EXPECT_EQ(MergeError(*store, same), "cannot merge store '" + same + "' into itself");
  }
  EXPECT_EQ(KeysOf(*store, "m"), Names{"k"});
}

TEST_F(MergeTest, WhatIsNoStoreIsRefused) {
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  testing::WriteFile(Path("notes.db"), "my notes\n");
  EXPECT_EQ(MergeError(*store, Path("notes.db")),
            "'" + Path("notes.db") + "' is not an areagraph store (not an SQLite database)");
  testing::ExecSql(Path("other.db"), "CREATE TABLE people (name TEXT)");
  EXPECT_EQ(MergeError(*store, Path("other.db")),
            "'" + Path("other.db") + "' is an SQLite database but not an areagraph store");
  EXPECT_EQ(MergeError(*store, Path("missing.db")),
            "store '" + Path("missing.db") + "' does not exist");
  EXPECT_FALSE(std::filesystem::exists(Path("missing.db")));
  EXPECT_NE(MergeError(*store, ":memory:").find("cannot merge from ':memory:'"), std::string::npos);
  EXPECT_EQ(ReadFile(Path("notes.db")), "my notes\n");
}

TEST_F(MergeTest, Version1StoreIsMergedAndLeftAsItIs) {
  const std::string old_path = Path("v1.db");
  testing::CreateVersion1Store(old_path);
  const std::string before = ReadFile(old_path);
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  const MaintenanceCounts added = store->MergeFrom(old_path);
  EXPECT_EQ(added.maps, 1);
  EXPECT_EQ(added.artifacts, 2);
  EXPECT_EQ(added.failures, 0);
  EXPECT_EQ(store->ReadHeadKey("old_map", "clean"), "v1-clean");
  EXPECT_EQ(store->ReadMap("old_map")->source_path, "old.png");
  EXPECT_EQ(ReadFile(old_path), before);
  EXPECT_EQ(testing::QueryColumn(old_path, "PRAGMA user_version"), Names{"1"});
}

TEST_F(MergeTest, FailedMergeChangesNothingAndTheNextOneWorks) {
  const std::string main_path = Path("main.db"), bad = Path("bad.db"), good = Path("good.db");
  OpenArtifactStore(main_path)->WriteArtifact(Artifact("m", "clean", "k", {"i"}));
  {
    std::unique_ptr<ArtifactStore> source = OpenArtifactStore(bad);
    source->WriteArtifact(Artifact("bad_a", "import", "a1", {"file"}));
    source->WriteArtifact(Artifact("bad_b", "import", "b1", {"file"}));
  }
  // A hand-edited source whose second map's artifact breaks a NOT NULL rule
  // here: the maps copied before it must not stay.
  testing::ExecSql(bad,
                   "PRAGMA writable_schema = ON;"
                   "UPDATE sqlite_master SET sql = replace(sql, 'created_at TEXT NOT NULL', "
                   "'created_at TEXT') WHERE name = 'artifacts';");
  // Sealed again: a row that passes its own check, so that the copy itself fails.
  testing::ExecSqlAndReseal(bad, "UPDATE artifacts SET created_at = NULL WHERE cache_key = 'b1'");
  OpenArtifactStore(good)->WriteArtifact(Artifact("g", "clean", "g1", {"i"}));

  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(main_path);
  const std::string error = MergeError(*store, bad);
  EXPECT_NE(error.find("NOT NULL"), std::string::npos) << error;
  EXPECT_EQ(MapNames(*store), Names{"m"});
  EXPECT_EQ(store->MergeFrom(good).artifacts, 1);  // the bad store was detached
  EXPECT_EQ(MapNames(*store), (Names{"g", "m"}));
}

// A payload that fails its digest in the input is refused by the input's
// name, and nothing of that input is merged (one transaction).
TEST_F(MergeTest, CorruptPayloadInTheInputIsRefusedAndNothingIsCopied) {
  {
    std::unique_ptr<ArtifactStore> shard = OpenArtifactStore(Path("shard.db"));
    shard->WriteArtifact(Import("lab_a", "ia", "a.png"));
    shard->WriteArtifact(Artifact("lab_a", "clean", "ca", {"ia"}, "clean a payload"));
    shard->WriteArtifact(Import("lab_b", "ib", "b.png"));
  }
  // Well-formed bytes that are not what was written (a flipped byte of the
  // zstd frame is refused too, in other words).
  testing::ExecSql(Path("shard.db"),
                   "UPDATE artifacts SET payload_codec = 0, payload = X'0a0178'"
                   " WHERE cache_key = 'ca'");
  std::unique_ptr<ArtifactStore> out = OpenArtifactStore(Path("out.db"));
  out->WriteArtifact(Import("kept", "ik", "k.png"));
  EXPECT_EQ(MergeError(*out, Path("shard.db")),
            "store '" + Path("shard.db") +
                "' is damaged: artifact ca of map 'lab_a' (clean) has a corrupt payload (payload "
                "digest mismatch); nothing was merged from it (ag-store verify --store " +
                Path("shard.db") + " lists the problems)");
  EXPECT_EQ(MapNames(*out), Names{"kept"});
  EXPECT_TRUE(out->Verify({"import"}).empty());
}

// Only what is copied is checked: a damaged artifact that the output already
// holds (same key) is not copied, so it does not stop the merge.
TEST_F(MergeTest, DamagedArtifactTheOutputAlreadyHoldsIsNotCopied) {
  OpenArtifactStore(Path("shard.db"))->WriteArtifact(Import("lab_a", "ia", "a.png"));
  OpenArtifactStore(Path("out.db"))->WriteArtifact(Import("lab_a", "ia", "a.png"));
  testing::FlipPayloadByte(Path("shard.db"), "ia", 0);
  std::unique_ptr<ArtifactStore> out = OpenArtifactStore(Path("out.db"));
  EXPECT_EQ(MergeError(*out, Path("shard.db")), "");
  EXPECT_TRUE(out->Verify({"import"}).empty());
}

// SQLite-level damage in the input (an index page) is refused by name too.
TEST_F(MergeTest, InputWithDamagedPagesIsRefusedByName) {
  {
    std::unique_ptr<ArtifactStore> shard = OpenArtifactStore(Path("shard.db"));
    for (int map = 0; map < 40; ++map) {
      const std::string name = "map_" + std::to_string(map);
      shard->WriteArtifact(Import(name, "i" + name, name + ".png"));
    }
  }
  testing::DamageRootPage(Path("shard.db"), "artifacts_by_map_and_time", 512);
  std::unique_ptr<ArtifactStore> out = OpenArtifactStore(Path("out.db"));
  const std::string error = MergeError(*out, Path("shard.db"));
  EXPECT_EQ(error.rfind("store '" + Path("shard.db") + "' is damaged (SQLite: ", 0), 0u) << error;
  EXPECT_NE(error.find("nothing was merged from it"), std::string::npos) << error;
  EXPECT_TRUE(MapNames(*out).empty());
}

}  // namespace
}  // namespace areagraph
