// Reading a collection index as a store: rows from the index, payloads from
// the shard stores it names. Verify is in collection_index_verify.cc.

#include "store/collection_index_store.h"

#include <sqlite3.h>

#include <algorithm>
#include <filesystem>

#include "common/error.h"
#include "common/text.h"
#include "store/collection_index_sql.h"
#include "store/sqlite_artifact_store.h"
#include "store/sqlite_store_sql.h"
#include "store/sqlite_versions_sql.h"

namespace areagraph {
namespace {

namespace fs = std::filesystem;

// The user_version of the open database, or -1 when SQLite cannot read it
// (not an SQLite file). Always read through SQLite, never by opening the
// file directly: closing another descriptor of a file drops the POSIX locks
// that SQLite holds on it in this process, and a writer's log could then be
// removed under it by another process.
int64_t UserVersion(sqlite3* db) {
  sqlite3_stmt* statement = nullptr;
  int64_t version = -1;
  if (sqlite3_prepare_v2(db, "PRAGMA user_version", -1, &statement, nullptr) == SQLITE_OK &&
      sqlite3_step(statement) == SQLITE_ROW) {
    version = sqlite3_column_int64(statement, 0);
  }
  sqlite3_finalize(statement);
  return version;
}

std::string ShardError(const std::string& map_name, const std::string& shard,
                       const std::string& index, const std::string& problem) {
  return "map '" + map_name + "' is in shard store '" + shard + "' of collection index '" + index +
         "', which " + problem;
}

}  // namespace

bool IsCollectionIndex(const std::string& path) {
  if (path == kMemoryStorePath || !fs::is_regular_file(path)) return false;
  try {
    const SqliteConnection connection(path, StoreMode::kReadOnly);
    // A log beside the store may be one left for the next writer (ag-run
    // hands its store to its workers so): closing as the last connection
    // must not fold it. Without a log there is nothing to fold, and the
    // close removes the side files this read made.
    if (fs::exists(path + "-wal")) {
      sqlite3_db_config(connection.get(), SQLITE_DBCONFIG_NO_CKPT_ON_CLOSE, 1, nullptr);
    }
    return UserVersion(connection.get()) > kCollectionIndexVersionBase;
  } catch (const StoreError&) {
    return false;  // the ordinary open says what is wrong
  }
}

CollectionIndexStore::CollectionIndexStore(const std::string& path)
    : path_(path), connection_(path, StoreMode::kReadOnly), db_(connection_.get()) {
  const int64_t version = UserVersion(db_) - kCollectionIndexVersionBase;
  if (version > kCollectionIndexSchemaVersion) {
    throw StoreError("collection index '" + path + "' has index schema version " +
                     std::to_string(version) + ", newer than this build's " +
                     std::to_string(kCollectionIndexSchemaVersion) + "; upgrade areagraph");
  }
  if (version < 1) throw StoreError("'" + path + "' is not a collection index");
  {
    SqliteStatement collection(db_, path_, collection_sql::kReadCollection,
                               "reading the collection index");
    StatementUse use(collection);
    if (!collection.Step()) {
      throw StoreError("collection index '" + path_ + "' is damaged (no collection row)");
    }
    info_.head_stages =
        store_internal::SplitLines(collection.ColumnText(0, "collection.head_stages"));
  }
  const fs::path folder = fs::path(path).parent_path();
  SqliteStatement shards(db_, path_, collection_sql::kReadShards, "reading the shards");
  StatementUse use(shards);
  while (shards.Step()) {
    CollectionShard shard;
    shard.id = shards.ColumnInt64(0, "shards.id");
    shard.path = shards.ColumnText(1, "shards.path");
    shard.resolved_path = (folder / shard.path).lexically_normal().string();
    shard.maps = shards.ColumnInt64(2, "shards.maps");
    shard.artifacts = shards.ColumnInt64(3, "shards.artifacts");
    info_.shards.push_back(std::move(shard));
  }
  using namespace collection_sql;
  const auto prepare = [&](const char* sql, const char* action) {
    return LazyStatement(db_, path_, sql, action);
  };
  // The index's maps, heads, versions and failures tables answer the store's
  // own statements; its artifacts table has statements of its own.
  sql_read_all_maps_ = prepare(store_sql::kReadAllMaps, "reading the maps");
  sql_read_map_ = prepare(store_sql::kReadMap, "reading a map");
  sql_read_artifact_ = prepare(kReadArtifact, "reading an artifact");
  sql_read_head_ = prepare(kReadHead, "reading a head artifact");
  sql_read_artifact_summaries_ = prepare(kReadArtifactSummaries, "listing the artifacts of a map");
  sql_count_artifacts_ = prepare(kCountArtifacts, "counting the artifacts of a map");
  sql_has_artifact_ = prepare(store_sql::kHasArtifact, "looking up an artifact");
  sql_read_head_key_ = prepare(store_sql::kReadHeadKey, "looking up a head");
  sql_read_versions_ = prepare(store_sql::kReadVersions, "reading the history of a map");
  sql_read_version_ = prepare(store_sql::kReadVersion, "reading a version");
  sql_read_failures_ = prepare(store_sql::kReadFailures, "reading the failures");
}

std::unique_ptr<ArtifactStore> OpenCollectionIndexStore(const std::string& path, StoreMode mode) {
  auto index = std::make_unique<CollectionIndexStore>(path);
  if (mode == StoreMode::kReadWrite) {
    throw StoreError("'" + path + "' is a collection index of " +
                     std::to_string(index->info().shards.size()) +
                     " shard stores, which is only read: run on a shard store (--store "
                     "SHARD.db) and then ag-store index again");
  }
  return index;
}

std::vector<MapRecord> CollectionIndexStore::ReadAllMaps() {
  std::vector<MapRecord> maps;
  SqliteStatement& statement = *sql_read_all_maps_;
  StatementUse use(statement);
  while (statement.Step()) {
    maps.push_back({statement.ColumnInt64(0, "maps.id"), statement.ColumnText(1, "maps.name"),
                    statement.ColumnText(2, "maps.source_path"),
                    statement.ColumnText(3, "maps.source_digest")});
  }
  return maps;
}

std::optional<MapRecord> CollectionIndexStore::ReadMap(const std::string& map_name) {
  SqliteStatement& statement = *sql_read_map_;
  StatementUse use(statement);
  statement.BindText(1, map_name);
  if (!statement.Step()) return std::nullopt;
  return MapRecord{statement.ColumnInt64(0, "maps.id"), statement.ColumnText(1, "maps.name"),
                   statement.ColumnText(2, "maps.source_path"),
                   statement.ColumnText(3, "maps.source_digest")};
}

CollectionIndexStore::IndexedArtifact CollectionIndexStore::ReadIndexedRow(
    const SqliteStatement& statement, const std::string& map_name, int first) const {
  IndexedArtifact indexed;
  ArtifactRecord& artifact = indexed.record;
  artifact.map_name = map_name;
  artifact.stage = statement.ColumnText(first, "artifacts.stage");
  artifact.cache_key = statement.ColumnText(first + 1, "artifacts.cache_key");
  artifact.input_keys =
      store_internal::SplitLines(statement.ColumnText(first + 2, "artifacts.input_keys"));
  artifact.options_text = statement.ColumnText(first + 3, "artifacts.options");
  artifact.stage_version =
      static_cast<int>(statement.ColumnInt64(first + 4, "artifacts.stage_version"));
  artifact.proto_type = statement.ColumnText(first + 5, "artifacts.proto_type");
  artifact.payload_digest = statement.ColumnText(first + 6, "artifacts.payload_digest");
  artifact.created_at = statement.ColumnText(first + 7, "artifacts.created_at");
  artifact.elapsed_ms = statement.ColumnDouble(first + 8, "artifacts.elapsed_ms");
  artifact.is_head = statement.ColumnInt64(first + 9, "heads.artifact_id") != 0;
  artifact.summary_line = statement.ColumnText(first + 10, "artifacts.summary");
  artifact.payload_bytes = statement.ColumnInt64(first + 11, "artifacts.payload_size");
  indexed.shard_id = statement.ColumnInt64(first + 12, "maps.shard_id");
  indexed.detailed = statement.ColumnInt64(first + 13, "artifacts.summary") != 0;
  return indexed;
}

const CollectionShard* CollectionIndexStore::FindShard(int64_t shard_id,
                                                       const std::string& map_name) const {
  for (const CollectionShard& shard : info_.shards) {
    if (shard.id == shard_id) return &shard;
  }
  throw StoreError("collection index '" + path_ + "' is damaged: map '" + map_name +
                   "' names no shard it lists");
}

ArtifactStore& CollectionIndexStore::Shard(int64_t shard_id, const std::string& map_name) {
  auto open = open_shards_.find(shard_id);
  if (open != open_shards_.end()) return *open->second;
  const CollectionShard* shard = FindShard(shard_id, map_name);
  if (!fs::exists(shard->resolved_path)) {
    throw StoreError(ShardError(map_name, shard->path, path_,
                                "is missing (no file '" + shard->resolved_path + "')"));
  }
  if (IsCollectionIndex(shard->resolved_path)) {
    throw StoreError(ShardError(map_name, shard->path, path_, "is a collection index itself"));
  }
  try {
    open = open_shards_
               .emplace(shard_id, OpenArtifactStore(shard->resolved_path, StoreMode::kReadOnly))
               .first;
  } catch (const StoreError& error) {
    throw StoreError(
        ShardError(map_name, shard->path, path_, std::string("cannot be opened: ") + error.what()));
  }
  return *open->second;
}

namespace {

// What an index row without details takes from its shard's row.
void CopyDetails(const ArtifactRecord& from, ArtifactRecord& into) {
  into.payload_digest = from.payload_digest;
  into.payload_bytes = from.payload_bytes;
  into.summary_line = from.summary_line;
  into.elapsed_ms = from.elapsed_ms;
}

}  // namespace

StoreError CollectionIndexStore::ShardChanged(const IndexedArtifact& indexed, bool stored) const {
  const ArtifactRecord& artifact = indexed.record;
  return StoreError("artifact " + ShortKey(artifact.cache_key) + " (" + artifact.stage +
                    ") of map '" + artifact.map_name + "' is " +
                    (stored ? "another payload" : "no longer") + " in shard store '" +
                    FindShard(indexed.shard_id, artifact.map_name)->path +
                    "': the shard changed after collection index '" + path_ +
                    "' was written; run ag-store index again");
}

ArtifactRecord CollectionIndexStore::WithPayload(IndexedArtifact indexed) {
  ArtifactRecord& artifact = indexed.record;
  std::optional<ArtifactRecord> stored = Shard(indexed.shard_id, artifact.map_name)
                                             .ReadArtifact(artifact.map_name, artifact.cache_key);
  if (!stored) throw ShardChanged(indexed, false);
  if (!indexed.detailed) {
    CopyDetails(*stored, artifact);
  } else if (stored->payload_digest != artifact.payload_digest) {
    throw ShardChanged(indexed, true);
  }
  artifact.payload = std::move(stored->payload);
  artifact.payload_bytes = static_cast<int64_t>(artifact.payload.size());
  return std::move(artifact);
}

ArtifactRecord CollectionIndexStore::WithDetails(IndexedArtifact indexed) {
  if (indexed.detailed) return std::move(indexed.record);
  ArtifactRecord& artifact = indexed.record;
  const std::optional<ArtifactRecord> stored =
      Shard(indexed.shard_id, artifact.map_name)
          .ReadArtifactSummary(artifact.map_name, artifact.cache_key);
  if (!stored) throw ShardChanged(indexed, false);
  CopyDetails(*stored, artifact);
  return std::move(artifact);
}

std::optional<CollectionIndexStore::IndexedArtifact> CollectionIndexStore::ReadOneRow(
    LazyStatement& statement, const std::string& map_name, const std::string& second) {
  StatementUse use(*statement);
  statement->BindText(1, map_name);
  statement->BindText(2, second);
  if (!statement->Step()) return std::nullopt;
  return ReadIndexedRow(*statement, map_name, 0);
}

std::optional<ArtifactRecord> CollectionIndexStore::ReadArtifact(const std::string& map_name,
                                                                 const std::string& cache_key) {
  std::optional<IndexedArtifact> indexed = ReadOneRow(sql_read_artifact_, map_name, cache_key);
  if (!indexed) return std::nullopt;
  return WithPayload(std::move(*indexed));
}

std::optional<ArtifactRecord> CollectionIndexStore::ReadHead(const std::string& map_name,
                                                             const std::string& stage) {
  std::optional<IndexedArtifact> indexed = ReadOneRow(sql_read_head_, map_name, stage);
  if (!indexed) return std::nullopt;
  return WithPayload(std::move(*indexed));
}

std::vector<ArtifactRecord> CollectionIndexStore::ReadArtifactSummaries(
    const std::string& map_name) {
  std::vector<IndexedArtifact> rows;
  {
    SqliteStatement& statement = *sql_read_artifact_summaries_;
    StatementUse use(statement);
    statement.BindText(1, map_name);
    while (statement.Step()) rows.push_back(ReadIndexedRow(statement, map_name, 0));
  }
  std::vector<ArtifactRecord> summaries;
  const bool all_detailed = std::all_of(rows.begin(), rows.end(),
                                        [](const IndexedArtifact& row) { return row.detailed; });
  if (all_detailed) {
    for (IndexedArtifact& row : rows) summaries.push_back(std::move(row.record));
    return summaries;
  }
  // One read of the map's rows in its shard rather than one per artifact.
  std::map<std::string, ArtifactRecord> stored;
  for (ArtifactRecord& record :
       Shard(rows.front().shard_id, map_name).ReadArtifactSummaries(map_name)) {
    stored.emplace(record.cache_key, std::move(record));
  }
  for (IndexedArtifact& row : rows) {
    if (!row.detailed) {
      const auto found = stored.find(row.record.cache_key);
      if (found == stored.end()) throw ShardChanged(row, false);
      CopyDetails(found->second, row.record);
    }
    summaries.push_back(std::move(row.record));
  }
  return summaries;
}

std::optional<ArtifactRecord> CollectionIndexStore::ReadArtifactSummary(
    const std::string& map_name, const std::string& cache_key) {
  std::optional<IndexedArtifact> indexed = ReadOneRow(sql_read_artifact_, map_name, cache_key);
  if (!indexed) return std::nullopt;
  return WithDetails(std::move(*indexed));
}

int64_t CollectionIndexStore::CountArtifacts(const std::string& map_name) {
  SqliteStatement& statement = *sql_count_artifacts_;
  StatementUse use(statement);
  statement.BindText(1, map_name);
  statement.Step();
  return statement.ColumnInt64(0, "count(*)");
}

bool CollectionIndexStore::HasArtifact(const std::string& map_name, const std::string& cache_key) {
  SqliteStatement& statement = *sql_has_artifact_;
  StatementUse use(statement);
  statement.BindText(1, map_name);
  statement.BindText(2, cache_key);
  return statement.Step();
}

std::optional<std::string> CollectionIndexStore::ReadHeadKey(const std::string& map_name,
                                                             const std::string& stage) {
  SqliteStatement& statement = *sql_read_head_key_;
  StatementUse use(statement);
  statement.BindText(1, map_name);
  statement.BindText(2, stage);
  if (!statement.Step()) return std::nullopt;
  return statement.ColumnText(0, "artifacts.cache_key");
}

std::vector<VersionRecord> CollectionIndexStore::ReadVersions(const std::string& map_name) {
  SqliteStatement& statement = *sql_read_versions_;
  StatementUse use(statement);
  statement.BindText(1, map_name);
  std::vector<VersionRecord> versions;
  while (statement.Step()) versions.push_back(store_internal::ReadVersionRow(statement));
  return versions;
}

std::optional<VersionRecord> CollectionIndexStore::ReadVersion(const std::string& map_name,
                                                               const std::string& cache_key) {
  SqliteStatement& statement = *sql_read_version_;
  StatementUse use(statement);
  statement.BindText(1, map_name);
  statement.BindText(2, cache_key);
  if (!statement.Step()) return std::nullopt;
  return store_internal::ReadVersionRow(statement);
}

std::vector<FailureRecord> CollectionIndexStore::ReadFailures() {
  SqliteStatement& statement = *sql_read_failures_;
  StatementUse use(statement);
  std::vector<FailureRecord> failures;
  while (statement.Step()) failures.push_back(store_internal::ReadFailureRow(statement));
  return failures;
}

void CollectionIndexStore::ThrowReadOnly(const std::string& what) const {
  throw StoreError("cannot " + what + " collection index '" + path_ +
                   "': an index is only read; write to its shard stores and index them again");
}

void CollectionIndexStore::WriteArtifact(const NewArtifact&) { ThrowReadOnly("write to"); }
void CollectionIndexStore::UpdateHead(const std::string&, const std::string&) {
  ThrowReadOnly("write to");
}
void CollectionIndexStore::RecordFailure(const FailureRecord&) { ThrowReadOnly("write to"); }
void CollectionIndexStore::ClearFailure(const std::string&) { ThrowReadOnly("write to"); }
MaintenanceCounts CollectionIndexStore::CollectGarbage() { ThrowReadOnly("collect garbage in"); }
MaintenanceCounts CollectionIndexStore::MergeFrom(const std::string&) {
  ThrowReadOnly("merge into");
}

void CollectionIndexStore::BackupTo(const std::string&) {
  throw StoreError("'" + path_ +
                   "' is a collection index: copy its folder with the shard stores instead, or "
                   "make one store file of it with ag-store merge OUT " +
                   path_);
}

}  // namespace areagraph
