// A collection index (store/collection_index.h) over small shard stores:
// read as one store, moved with its folder, and what happens when a shard is
// missing, damaged or changed after indexing.
#include "store/collection_index.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

#include "common/error.h"
#include "tests/store/maintenance_helpers.h"
#include "tests/support/raw_sqlite.h"
#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kFileInputStages = {"import"};
const std::vector<std::string> kFinalStages = {"merge", "match"};

// A map's three artifacts, import -> merge -> match, all heads; match is
// recorded as the map's first version.
void WriteMap(ArtifactStore& store, const std::string& map_name) {
  store.WriteArtifact(
      Artifact(map_name, "import", map_name + "-import", {"file-digest"}, map_name + " grid"));
  store.WriteArtifact(Artifact(map_name, "merge", map_name + "-merge", {map_name + "-import"},
                               map_name + " graph"));
  NewArtifact match = Artifact(map_name, "match", map_name + "-match", {map_name + "-merge"},
                               map_name + " stable graph");
  match.version = VersionLink{"", 1};
  store.WriteArtifact(match);
}

class CollectionIndexTest : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(folder());
    {
      auto a = OpenArtifactStore(shard("a"));
      WriteMap(*a, "hall");
      WriteMap(*a, "lab");
      a->RecordFailure({"broken", "import", "not an image", "broken.png", ""});
    }
    {
      auto b = OpenArtifactStore(shard("b"));
      WriteMap(*b, "office");
      // A map whose merge failed: an import and nothing after it.
      b->WriteArtifact(Artifact("stairs", "import", "stairs-import", {"file-digest"}));
      b->RecordFailure({"stairs", "merge", "no areas", "stairs.png", ""});
    }
  }

  std::string folder() const { return dir_.File("collection"); }
  std::string shard(const std::string& name) const { return folder() + "/" + name + ".db"; }
  std::string index() const { return folder() + "/collection.db"; }

  // A new index of both shards (the API writes a new file; ag-store replaces one).
  std::vector<CollectionShard> Index(const std::vector<std::string>& head_stages = {}) {
    fs::remove(index());
    return WriteCollectionIndex(index(), index(), {shard("a"), shard("b")}, head_stages,
                                kFinalStages);
  }

  TempDir dir_;
};

TEST_F(CollectionIndexTest, ReadsAsOneStoreOfItsShards) {
  const std::vector<CollectionShard> shards = Index();
  ASSERT_EQ(shards.size(), 2u);
  EXPECT_EQ(shards[0].path, "a.db");
  EXPECT_EQ(shards[0].maps, 2);
  EXPECT_EQ(shards[0].artifacts, 6);
  EXPECT_EQ(shards[1].maps, 2);
  EXPECT_EQ(shards[1].artifacts, 4);
  ASSERT_TRUE(IsCollectionIndex(index()));
  EXPECT_FALSE(IsCollectionIndex(shard("a")));
  EXPECT_FALSE(IsCollectionIndex(dir_.File("nothing.db")));

  auto store = OpenArtifactStore(index(), StoreMode::kReadOnly);
  EXPECT_EQ(MapNames(*store), (std::vector<std::string>{"hall", "lab", "office", "stairs"}));
  const std::optional<ArtifactRecord> head = store->ReadHead("office", "match");
  ASSERT_TRUE(head);
  EXPECT_EQ(head->payload, ProtoBytes("office stable graph"));
  EXPECT_TRUE(head->is_head);
  EXPECT_EQ(head->input_keys, std::vector<std::string>{"office-merge"});
  const std::optional<ArtifactRecord> by_key = store->ReadArtifact("lab", "lab-import");
  ASSERT_TRUE(by_key);
  EXPECT_EQ(by_key->payload, ProtoBytes("lab grid"));
  EXPECT_FALSE(store->ReadArtifact("lab", "office-import"));
  EXPECT_EQ(KeysOf(*store, "hall"),
            (std::vector<std::string>{"hall-import", "hall-match", "hall-merge"}));
  EXPECT_EQ(store->ReadHeadKey("stairs", "import"), "stairs-import");
  EXPECT_TRUE(store->HasArtifact("hall", "hall-merge"));
  EXPECT_FALSE(store->HasArtifact("hall", "lab-merge"));

  // What a shard answers, the index answers, row for row: the final stages'
  // rows from the index itself, the others' details from the shard.
  auto b = OpenArtifactStore(shard("b"), StoreMode::kReadOnly);
  for (const std::string key : {"office-merge", "office-import"}) {
    const std::optional<ArtifactRecord> in_shard = b->ReadArtifactSummary("office", key);
    const std::optional<ArtifactRecord> in_index = store->ReadArtifactSummary("office", key);
    ASSERT_TRUE(in_shard && in_index);
    EXPECT_EQ(in_index->created_at, in_shard->created_at);
    EXPECT_EQ(in_index->payload_digest, in_shard->payload_digest);
    EXPECT_EQ(in_index->payload_bytes, in_shard->payload_bytes);
    EXPECT_EQ(in_index->summary_line, in_shard->summary_line);
    EXPECT_EQ(in_index->elapsed_ms, in_shard->elapsed_ms);
    EXPECT_EQ(in_index->input_keys, in_shard->input_keys);
  }
  const std::vector<ArtifactRecord> rows = store->ReadArtifactSummaries("office");
  const std::vector<ArtifactRecord> shard_rows = b->ReadArtifactSummaries("office");
  ASSERT_EQ(rows.size(), shard_rows.size());
  for (size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].cache_key, shard_rows[i].cache_key);
    EXPECT_EQ(rows[i].summary_line, shard_rows[i].summary_line);
    EXPECT_EQ(rows[i].is_head, shard_rows[i].is_head);
  }
  EXPECT_EQ(store->CountArtifacts("office"), 3);
  EXPECT_EQ(QueryColumn(index(),
                        "SELECT stage FROM artifacts WHERE summary IS NOT NULL"
                        " ORDER BY stage"),
            (std::vector<std::string>{"match", "match", "match", "merge", "merge", "merge"}))
      << "only the final stages' rows hold their details";
  const std::vector<VersionRecord> versions = store->ReadVersions("lab");
  ASSERT_EQ(versions.size(), 1u);
  EXPECT_EQ(versions[0].cache_key, "lab-match");
  EXPECT_TRUE(versions[0].stored);
  EXPECT_TRUE(versions[0].is_head);
  const std::vector<FailureRecord> failures = store->ReadFailures();
  ASSERT_EQ(failures.size(), 2u);
  EXPECT_EQ(failures[0].map_name, "broken");
  EXPECT_EQ(failures[1].map_name, "stairs");

  EXPECT_TRUE(VerifyCollectionIndex(index(), kFileInputStages, nullptr, StructureCheck::kFull,
                                    ShardCheck::kFull)
                  .empty());
}

TEST_F(CollectionIndexTest, IsOnlyRead) {
  Index();
  const std::string refused =
      ErrorOf<StoreError>([&] { OpenArtifactStore(index(), StoreMode::kReadWrite); });
  EXPECT_NE(refused.find("'" + index() +
                         "' is a collection index of 2 shard stores, which is only "
                         "read"),
            std::string::npos)
      << refused;
  auto store = OpenArtifactStore(index(), StoreMode::kReadOnly);
  EXPECT_NE(ErrorOf<StoreError>([&] {
              store->WriteArtifact(Artifact("x", "import", "k", {}));
            }).find("an index is only read"),
            std::string::npos);
  EXPECT_NE(
      ErrorOf<StoreError>([&] { store->BackupTo(dir_.File("copy.db")); }).find("copy its folder"),
      std::string::npos);
  auto other = OpenArtifactStore(dir_.File("other.db"));
  EXPECT_NE(ErrorOf<StoreError>([&] {
              other->MergeFrom(index());
            }).find("merge the shard stores it names"),
            std::string::npos);
}

TEST_F(CollectionIndexTest, FinalStagesOnly) {
  const std::vector<CollectionShard> shards = Index(kFinalStages);
  EXPECT_EQ(shards[0].artifacts, 4);
  EXPECT_EQ(shards[1].maps, 1) << "stairs has no merge or match head";
  auto store = OpenArtifactStore(index(), StoreMode::kReadOnly);
  EXPECT_EQ(MapNames(*store), (std::vector<std::string>{"hall", "lab", "office"}));
  EXPECT_EQ(KeysOf(*store, "hall"), (std::vector<std::string>{"hall-match", "hall-merge"}));
  EXPECT_FALSE(store->ReadHead("hall", "import"));
  ASSERT_TRUE(store->ReadHead("hall", "match"));
  EXPECT_EQ(store->ReadFailures().size(), 2u);
  EXPECT_EQ(ReadCollectionIndexInfo(index()).head_stages, kFinalStages);
  // The rest stays in the shards, unindexed: no problem for verify.
  EXPECT_TRUE(VerifyCollectionIndex(index(), kFileInputStages, nullptr, StructureCheck::kFull,
                                    ShardCheck::kIndexedRowsOnly)
                  .empty());
}

TEST_F(CollectionIndexTest, MovedFolderStillReads) {
  Index();
  const std::string moved = dir_.File("elsewhere/deeper");
  fs::create_directories(fs::path(moved).parent_path());
  fs::rename(folder(), moved);
  auto store = OpenArtifactStore(moved + "/collection.db", StoreMode::kReadOnly);
  const std::optional<ArtifactRecord> head = store->ReadHead("office", "merge");
  ASSERT_TRUE(head);
  EXPECT_EQ(head->payload, ProtoBytes("office graph"));
  EXPECT_TRUE(VerifyCollectionIndex(moved + "/collection.db", kFileInputStages, nullptr,
                                    StructureCheck::kFull, ShardCheck::kFull)
                  .empty());
}

TEST_F(CollectionIndexTest, ShardsOutsideTheFolderAreNamedRelatively) {
  const std::string outside = dir_.File("indexes/c.db");
  fs::create_directories(fs::path(outside).parent_path());
  const std::vector<CollectionShard> shards =
      WriteCollectionIndex(outside, outside, {shard("a")}, {}, kFinalStages);
  EXPECT_EQ(shards[0].path, "../collection/a.db");
  auto store = OpenArtifactStore(outside, StoreMode::kReadOnly);
  EXPECT_TRUE(store->ReadHead("hall", "match"));
}

TEST_F(CollectionIndexTest, MissingShardIsNamedWithTheMap) {
  Index();
  fs::rename(shard("b"), dir_.File("b-elsewhere.db"));
  auto store = OpenArtifactStore(index(), StoreMode::kReadOnly);
  EXPECT_TRUE(store->ReadHead("hall", "match")) << "the other shard still reads";
  EXPECT_TRUE(store->ReadArtifactSummary("office", "office-match")) << "rows come from the index";
  const std::string error = ErrorOf<StoreError>([&] { store->ReadHead("office", "match"); });
  EXPECT_EQ(error, "map 'office' is in shard store 'b.db' of collection index '" + index() +
                       "', which is missing (no file '" + shard("b") + "')");

  const std::vector<VerifyProblem> problems = VerifyCollectionIndex(
      index(), kFileInputStages, nullptr, StructureCheck::kFull, ShardCheck::kIndexedRowsOnly);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].map_name, "office");
  EXPECT_EQ(problems[0].problem, "shard store 'b.db' is missing (no file '" + shard("b") +
                                     "'): the index's 2 maps in it ('office' and 1 more) cannot "
                                     "be read");
}

TEST_F(CollectionIndexTest, DamagedShardIsNamed) {
  Index();
  FlipPayloadByte(shard("a"), "lab-merge", 3);
  auto store = OpenArtifactStore(index(), StoreMode::kReadOnly);
  const std::string error = ErrorOf<StoreError>([&] { store->ReadHead("lab", "merge"); });
  EXPECT_NE(error.find("of map 'lab' in store '" + shard("a") + "' is corrupt"), std::string::npos)
      << error;
  const std::vector<VerifyProblem> problems = VerifyCollectionIndex(
      index(), kFileInputStages, nullptr, StructureCheck::kFull, ShardCheck::kFull);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].map_name, "lab");
  EXPECT_EQ(problems[0].cache_key, "lab-merge");
  EXPECT_EQ(problems[0].problem.rfind("in shard store 'a.db': ", 0), 0u) << problems[0].problem;
  // Without payloads the damage is not seen; the rows still agree.
  EXPECT_TRUE(VerifyCollectionIndex(index(), kFileInputStages, nullptr, StructureCheck::kFull,
                                    ShardCheck::kIndexedRowsOnly)
                  .empty());

  WriteFile(shard("b"), "this is not a store any more");
  const std::vector<VerifyProblem> unreadable = VerifyCollectionIndex(
      index(), kFileInputStages, nullptr, StructureCheck::kFull, ShardCheck::kIndexedRowsOnly);
  ASSERT_EQ(unreadable.size(), 1u);
  EXPECT_NE(unreadable[0].problem.find("map 'office' is in shard store 'b.db' of collection "
                                       "index '" +
                                       index() + "', which cannot be opened"),
            std::string::npos)
      << unreadable[0].problem;
}

TEST_F(CollectionIndexTest, ChangedShardIsReportedUntilIndexedAgain) {
  Index();
  {
    auto b = OpenArtifactStore(shard("b"));
    b->WriteArtifact(Artifact("stairs", "merge", "stairs-merge", {"stairs-import"}));
    b->ClearFailure("stairs");
    WriteMap(*b, "attic");
    // The office's merge computed again under another key: the head moves.
    b->WriteArtifact(Artifact("office", "merge", "new-office-merge", {"office-import"}));
  }
  const auto problems = [&] {
    std::vector<std::string> lines;
    for (const VerifyProblem& problem :
         VerifyCollectionIndex(index(), kFileInputStages, nullptr, StructureCheck::kFull,
                               ShardCheck::kIndexedRowsOnly)) {
      lines.push_back(problem.map_name + " " + problem.stage + ": " + problem.problem);
    }
    return lines;
  };
  const std::string changed =
      ": the shard changed after the index was written; run ag-store index again";
  EXPECT_EQ(problems(),
            (std::vector<std::string>{
                "office merge: head in shard store 'b.db': new-office-m, in the "
                "index: office-merge" +
                    changed,
                "stairs merge: head in shard store 'b.db': stairs-merge, in the "
                "index: none" +
                    changed,
                "attic : shard store 'b.db' holds this map, which the index lacks" + changed}));
  Index();
  EXPECT_EQ(problems(), std::vector<std::string>{});
  auto store = OpenArtifactStore(index(), StoreMode::kReadOnly);
  EXPECT_TRUE(store->ReadHead("attic", "match"));
  EXPECT_EQ(store->ReadFailures().size(), 1u) << "stairs no longer failed";
}

TEST_F(CollectionIndexTest, ArtifactGoneFromItsShard) {
  Index();
  ExecSql(shard("a"), "DELETE FROM artifacts WHERE cache_key = 'hall-import'");
  auto store = OpenArtifactStore(index(), StoreMode::kReadOnly);
  const std::string error = ErrorOf<StoreError>([&] { store->ReadHead("hall", "import"); });
  EXPECT_EQ(error,
            "artifact hall-import (import) of map 'hall' is no longer in shard store "
            "'a.db': the shard changed after collection index '" +
                index() + "' was written; run ag-store index again");
  const std::vector<VerifyProblem> problems = VerifyCollectionIndex(
      index(), kFileInputStages, nullptr, StructureCheck::kFull, ShardCheck::kIndexedRowsOnly);
  ASSERT_GE(problems.size(), 1u);
  EXPECT_EQ(problems[0].cache_key, "hall-import");
  EXPECT_NE(problems[0].problem.find("not in shard store 'a.db' any more"), std::string::npos);
}

TEST_F(CollectionIndexTest, RefusesWhatIsNotOneCollection) {
  Index();
  const auto refusal = [&](const std::vector<std::string>& shards) {
    return ErrorOf<StoreError>(
        [&] { WriteCollectionIndex(dir_.File("new.db"), dir_.File("new.db"), shards, {}, {}); });
  };
  EXPECT_NE(refusal({index()}).find("is a collection index, not a shard store"), std::string::npos);
  EXPECT_NE(refusal({shard("a"), shard("a")}).find("is named twice"), std::string::npos);
  EXPECT_NE(refusal({dir_.File("none.db")}).find("does not exist"), std::string::npos);
  fs::copy_file(shard("a"), dir_.File("a-copy.db"));
  EXPECT_EQ(refusal({shard("a"), dir_.File("a-copy.db")}),
            "map 'hall' is in shard store '" + dir_.File("a-copy.db") +
                "' and in 'collection/a.db'; a collection keeps each map in one shard (ag-store "
                "merge them first)");
  RewriteAsSchema4(dir_.File("a-copy.db"));
  EXPECT_NE(refusal({dir_.File("a-copy.db")}).find("has schema version 4; an index needs 5"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(dir_.File("new.db"))) << "a refused index leaves no file";
}

TEST_F(CollectionIndexTest, NewerIndexSchemaIsRefused) {
  Index();
  ExecSql(index(), "PRAGMA user_version = " + std::to_string(kCollectionIndexVersionBase +
                                                             kCollectionIndexSchemaVersion + 1));
  EXPECT_EQ(ErrorOf<StoreError>([&] { OpenArtifactStore(index(), StoreMode::kReadOnly); }),
            "collection index '" + index() + "' has index schema version " +
                std::to_string(kCollectionIndexSchemaVersion + 1) + ", newer than this build's " +
                std::to_string(kCollectionIndexSchemaVersion) + "; upgrade areagraph");
}

TEST_F(CollectionIndexTest, KeepOnlyHeadsOfTheFinalStages) {
  {
    auto a = OpenArtifactStore(shard("a"));
    // A superseded graph of the hall, no longer a head.
    a->WriteArtifact(Artifact("hall", "merge", "hall-merge-old", {"hall-import"}));
    a->WriteArtifact(Artifact("hall", "merge", "hall-merge", {"hall-import"}, "hall graph"));
  }
  const MaintenanceCounts dropped = KeepOnlyHeadsOf(shard("a"), kFinalStages);
  EXPECT_EQ(dropped.artifacts, 3);  // two imports and the superseded merge
  EXPECT_EQ(dropped.maps, 0);
  auto a = OpenArtifactStore(shard("a"), StoreMode::kReadOnly);
  EXPECT_EQ(KeysOf(*a, "hall"), (std::vector<std::string>{"hall-match", "hall-merge"}));
  EXPECT_FALSE(a->ReadHeadKey("hall", "import")) << "the head went with its artifact";
  EXPECT_EQ(a->ReadVersions("hall").size(), 1u);
  // The merge heads' inputs are gone: a store's own verify says so, an index
  // of the final stages does not.
  EXPECT_EQ(a->Verify(kFileInputStages).size(), 2u);

  const MaintenanceCounts b_dropped = KeepOnlyHeadsOf(shard("b"), kFinalStages);
  EXPECT_EQ(b_dropped.maps, 1) << "stairs had no final head";
  EXPECT_EQ(OpenArtifactStore(shard("b"), StoreMode::kReadOnly)->ReadFailures().size(), 1u);
  Index(kFinalStages);
  EXPECT_TRUE(VerifyCollectionIndex(index(), kFileInputStages, nullptr, StructureCheck::kFull,
                                    ShardCheck::kFull)
                  .empty());
  EXPECT_EQ(OpenArtifactStore(index(), StoreMode::kReadOnly)->ReadHead("lab", "match")->payload,
            ProtoBytes("lab stable graph"));
  EXPECT_NE(ErrorOf<StoreError>([&] {
              KeepOnlyHeadsOf(index(), kFinalStages);
            }).find("is a collection index"),
            std::string::npos);
}

}  // namespace
}  // namespace areagraph::testing
