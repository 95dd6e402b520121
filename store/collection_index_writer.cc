// Writing a collection index (ag-store index): each shard store is attached
// read-only and its rows, payloads left out, are copied into the new file.
// Also trimming a shard store to the heads that an index of the final stages
// reads (ag-store gc --keep final).

#include <sqlite3.h>

#include <filesystem>
#include <set>

#include "common/error.h"
#include "store/collection_index.h"
#include "store/collection_index_sql.h"
#include "store/sqlite_connection.h"
#include "store/sqlite_statement.h"
#include "store/sqlite_transaction.h"

namespace areagraph {
namespace {

namespace fs = std::filesystem;

// The oldest store schema an index reads: 5 added the payload sizes that
// summaries report without reading payloads.
constexpr int kOldestShardSchema = 5;

// The stages as a JSON array for json_each; stage names are plain words, but
// quotes and backslashes are escaped all the same.
std::string JsonArray(const std::vector<std::string>& words) {
  std::string json = "[";
  for (const std::string& word : words) {
    if (json.size() > 1) json += ',';
    json += '"';
    for (const char c : word) {
      if (c == '"' || c == '\\') json += '\\';
      json += c;
    }
    json += '"';
  }
  return json + "]";
}

std::string JoinLines(const std::vector<std::string>& lines) {
  std::string joined;
  for (const std::string& line : lines) joined += (joined.empty() ? "" : "\n") + line;
  return joined;
}

// `shard` relative to the folder the index lives in, so that moving the
// folder with its shards keeps the index valid.
std::string RelativeToIndex(const std::string& shard, const std::string& index_path) {
  const fs::path folder = fs::absolute(index_path).lexically_normal().parent_path();
  return fs::absolute(shard).lexically_normal().lexically_relative(folder).string();
}

// The checks that need no index file yet: every shard is a store this build
// reads (the ordinary open's checks), not an index, and named once.
void CheckShards(const std::vector<std::string>& shards, const std::string& final_path) {
  std::set<std::string> seen;
  for (const std::string& shard : shards) {
    if (IsCollectionIndex(shard)) {
      throw StoreError("'" + shard +
                       "' is a collection index, not a shard store; index its shards");
    }
    OpenArtifactStore(shard, StoreMode::kReadOnly);
    std::error_code ignored;
    if (fs::equivalent(shard, final_path, ignored)) {
      throw StoreError("'" + shard + "' is the index being written");
    }
    if (!seen.insert(fs::weakly_canonical(shard).string()).second) {
      throw StoreError("shard store '" + shard + "' is named twice");
    }
  }
}

class IndexWriter {
 public:
  explicit IndexWriter(const std::string& path)
      : path_(path), connection_(path, StoreMode::kReadWrite), db_(connection_.get()) {
    // A new file under a temporary name that nobody reads before it is
    // whole: a crash leaves a file the caller discards, so no journal.
    Exec("PRAGMA journal_mode = OFF", "writing the index without a journal");
  }

  void Run(const char* sql, const std::string& action,
           const std::function<void(SqliteStatement&)>& bind = nullptr) {
    SqliteStatement statement(db_, path_, sql, action);
    StatementUse use(statement);
    if (bind) bind(statement);
    while (statement.Step()) {
    }
  }

  void Exec(const char* sql, const std::string& action) {
    CheckSqlite(db_, path_, sqlite3_exec(db_, sql, nullptr, nullptr, nullptr), action);
  }

  void CreateSchema(const std::vector<std::string>& head_stages,
                    const std::vector<std::string>& detail_stages) {
    Exec("BEGIN", "starting the index");
    Exec(collection_sql::kCreateCollectionTable, "creating the collection table");
    Exec(collection_sql::kCreateShardsTable, "creating the shards table");
    Exec(collection_sql::kCreateMapsTable, "creating the maps table");
    Exec(collection_sql::kCreateArtifactsTable, "creating the artifacts table");
    Exec(collection_sql::kCreateArtifactsByTimeIndex, "creating the artifacts index");
    Exec(collection_sql::kCreateHeadsTable, "creating the heads table");
    Exec(collection_sql::kCreateVersionsTable, "creating the versions table");
    Exec(collection_sql::kCreateFailuresTable, "creating the failures table");
    Run(collection_sql::kWriteCollection, "recording the collection", [&](SqliteStatement& s) {
      s.BindText(1, JoinLines(head_stages));
      s.BindText(2, JoinLines(detail_stages));
    });
    Exec(("PRAGMA user_version = " +
          std::to_string(kCollectionIndexVersionBase + kCollectionIndexSchemaVersion))
             .c_str(),
         "setting the index's schema version");
    Exec("COMMIT", "writing the index's schema");
  }

  CollectionShard AddShard(const std::string& shard, const std::string& final_path,
                           const std::vector<std::string>& head_stages,
                           const std::vector<std::string>& detail_stages) {
    {
      SqliteStatement attach(db_, path_, collection_sql::kAttachShard,
                             "attaching shard '" + shard + "'");
      StatementUse use(attach);
      // Read-only: indexing never changes a shard.
      attach.BindText(1, StoreUri(shard, ReadAccess::kReadOnly));
      attach.Step();
    }
    struct Detach {
      sqlite3* db;
      ~Detach() { sqlite3_exec(db, collection_sql::kDetachShard, nullptr, nullptr, nullptr); }
    } detach{db_};
    CheckShardSchema(shard);
    CollectionShard added;
    added.path = RelativeToIndex(shard, final_path);
    added.resolved_path = shard;
    Exec("BEGIN", "indexing shard '" + shard + "'");
    CheckNoSharedMap(shard);
    {
      SqliteStatement insert(db_, path_, collection_sql::kInsertShard, "recording a shard");
      StatementUse use(insert);
      insert.BindText(1, added.path);
      insert.Step();
      added.id = insert.ColumnInt64(0, "shards.id");
    }
    const auto with_shard = [&](SqliteStatement& s) { s.BindInt64(1, added.id); };
    const std::string action = "indexing shard '" + shard + "': ";
    Run(collection_sql::kCopyMaps, action + "maps", with_shard);
    Run(collection_sql::kCopyArtifacts, action + "artifacts", [&](SqliteStatement& s) {
      s.BindInt64(1, added.id);
      if (!head_stages.empty()) s.BindText(2, JsonArray(head_stages));
      s.BindText(3, JsonArray(detail_stages));
    });
    if (!head_stages.empty()) {
      Run(collection_sql::kDropMapsWithoutArtifacts, action + "maps", with_shard);
    }
    Run(collection_sql::kCopyHeads, action + "heads", with_shard);
    Run(collection_sql::kCopyVersions, action + "versions", with_shard);
    Run(collection_sql::kCopyFailures, action + "failures", with_shard);
    {
      SqliteStatement count(db_, path_, collection_sql::kCountShardRows, action + "counting");
      StatementUse use(count);
      count.BindInt64(1, added.id);
      count.Step();
      added.maps = count.ColumnInt64(0, "shards.maps");
      added.artifacts = count.ColumnInt64(1, "shards.artifacts");
    }
    Exec("COMMIT", action + "committing");
    return added;
  }

 private:
  void CheckShardSchema(const std::string& shard) {
    SqliteStatement version(db_, path_, collection_sql::kReadShardVersion,
                            "reading the schema version of '" + shard + "'");
    StatementUse use(version);
    version.Step();
    const int64_t schema = version.ColumnInt64(0, "user_version");
    if (schema < kOldestShardSchema || schema > kStoreSchemaVersion) {
      throw StoreError("shard store '" + shard + "' has schema version " + std::to_string(schema) +
                       "; an index needs " + std::to_string(kOldestShardSchema) + " to " +
                       std::to_string(kStoreSchemaVersion) +
                       " (open an older store once for writing, e.g. ag-store gc --store " + shard +
                       ", to upgrade it)");
    }
  }

  void CheckNoSharedMap(const std::string& shard) {
    SqliteStatement shared(db_, path_, collection_sql::kFindSharedMap,
                           "comparing the maps of '" + shard + "'");
    StatementUse use(shared);
    if (!shared.Step()) return;
    throw StoreError("map '" + shared.ColumnText(0, "maps.name") + "' is in shard store '" + shard +
                     "' and in '" + shared.ColumnText(1, "shards.path") +
                     "'; a collection keeps each map in one shard (ag-store merge them first)");
  }

  const std::string path_;
  const SqliteConnection connection_;
  sqlite3* const db_;
};

}  // namespace

std::vector<CollectionShard> WriteCollectionIndex(const std::string& path,
                                                  const std::string& final_path,
                                                  const std::vector<std::string>& shards,
                                                  const std::vector<std::string>& head_stages,
                                                  const std::vector<std::string>& detail_stages) {
  if (shards.empty()) throw StoreError("an index needs at least one shard store");
  CheckShards(shards, final_path);
  std::vector<CollectionShard> added;
  try {
    IndexWriter writer(path);
    writer.CreateSchema(head_stages, detail_stages);
    for (const std::string& shard : shards) {
      added.push_back(writer.AddShard(shard, final_path, head_stages, detail_stages));
    }
  } catch (...) {
    std::error_code ignored;
    fs::remove(path, ignored);  // half an index is none
    throw;
  }
  return added;
}

MaintenanceCounts KeepOnlyHeadsOf(const std::string& store_path,
                                  const std::vector<std::string>& head_stages) {
  if (IsCollectionIndex(store_path)) {
    throw StoreError("'" + store_path + "' is a collection index; trim its shard stores");
  }
  if (head_stages.empty()) throw StoreError("name the stages whose heads to keep");
  // The usual checks (never creating a file), an older schema upgraded; then
  // a connection of our own for the statements below.
  OpenArtifactStore(store_path, StoreMode::kReadOnly);
  OpenArtifactStore(store_path, StoreMode::kReadWrite);
  const SqliteConnection connection(store_path, StoreMode::kReadWrite);
  sqlite3* db = connection.get();
  CheckSqlite(db, store_path, sqlite3_busy_timeout(db, kStoreBusyTimeoutMs),
              "setting the busy timeout");
  CheckSqlite(db, store_path,
              sqlite3_exec(db, "PRAGMA foreign_keys = ON", nullptr, nullptr, nullptr),
              "enabling foreign keys");
  SqliteStatement begin(db, store_path, "BEGIN IMMEDIATE", "starting a transaction");
  SqliteStatement commit(db, store_path, "COMMIT", "committing a transaction");
  SqliteStatement rollback(db, store_path, "ROLLBACK", "rolling back a transaction");
  SqliteTransaction transaction(db, begin, commit, rollback);
  const std::string stages = JsonArray(head_stages);
  MaintenanceCounts counts;
  {
    SqliteStatement count(db, store_path, collection_sql::kCountNotKept,
                          "counting the artifacts to drop");
    StatementUse use(count);
    count.BindText(1, stages);
    count.Step();
    counts.artifacts = count.ColumnInt64(0, "count(*)");
    counts.payload_bytes = count.ColumnInt64(1, "sum(payload_size)");
  }
  {
    SqliteStatement drop(db, store_path, collection_sql::kDeleteNotKept, "dropping artifacts");
    StatementUse use(drop);
    drop.BindText(1, stages);
    drop.Step();
  }
  {
    SqliteStatement drop(db, store_path, collection_sql::kDeleteMapsWithoutArtifacts,
                         "dropping empty maps");
    StatementUse use(drop);
    drop.Step();
    counts.maps = sqlite3_changes(db);
  }
  transaction.Commit();
  return counts;
}

}  // namespace areagraph
