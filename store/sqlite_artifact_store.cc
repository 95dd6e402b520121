// The SQLite implementation of ArtifactStore: opening and upgrading the
// file, reads, writes and failures. Maintenance is in sqlite_store_maintenance.cc.

#include "store/sqlite_artifact_store.h"

#include <sqlite3.h>

#include <chrono>
#include <memory>
#include <optional>
#include <thread>
#include <utility>

#include "common/error.h"
#include "common/text.h"
#include "store/collection_index_store.h"
#include "store/digest.h"
#include "store/payload_codec.h"
#include "store/payload_encoder.h"
#include "store/row_digest.h"
#include "store/sqlite_store_sql.h"
#include "store/sqlite_versions_sql.h"

namespace areagraph {

using store_internal::SplitLines;

namespace store_internal {

std::vector<std::string> SplitLines(const std::string& joined) {
  std::vector<std::string> lines;
  if (joined.empty()) return lines;
  size_t start = 0;
  while (true) {
    const size_t end = joined.find('\n', start);
    lines.push_back(joined.substr(start, end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return lines;
}

}  // namespace store_internal

namespace {

std::string JoinLines(const std::vector<std::string>& lines) {
  std::string joined;
  for (size_t i = 0; i < lines.size(); ++i) {
    if (i > 0) joined += '\n';
    joined += lines[i];
  }
  return joined;
}

}  // namespace

SqliteArtifactStore::SqliteArtifactStore(const std::string& path, StoreMode mode)
    : path_(path), mode_(mode), connection_(path, mode), db_(connection_.get()) {
  CheckSqlite(db_, path_, sqlite3_busy_timeout(db_, kStoreBusyTimeoutMs),
              "setting the busy timeout");
  store_internal::RegisterRowDigestFunction(db_, path_);
  const SchemaState state = ReadSchemaState();
  CheckIsAreagraphStore(state, mode);
  // Only now is the file known to be ours (or new) and may be changed.
  Exec("PRAGMA foreign_keys = ON", "enabling foreign keys");
  sql_stmt_begin_ = Prepare(store_sql::kBegin, "starting a transaction");
  sql_stmt_commit_ = Prepare(store_sql::kCommit, "committing a transaction");
  sql_stmt_rollback_ = Prepare(store_sql::kRollback, "rolling back a transaction");
  if (mode == StoreMode::kReadWrite) {
    if (sqlite3_db_readonly(db_, "main") == 1) {
      throw StoreError("cannot write store '" + path_ + "': the file is read-only");
    }
    if (path_ != kMemoryStorePath) EnableWriteAheadLog();
    schema_version_ = state.user_version;
    if (schema_version_ < kStoreSchemaVersion) CreateOrUpgradeSchema();
  } else if (path_ == kMemoryStorePath) {
    CreateOrUpgradeSchema();  // a private empty store; there is no file to protect
  } else {
    schema_version_ = state.user_version;  // read as it is, even if older
  }
  PrepareStatements();
}

SqliteArtifactStore::SqliteArtifactStore(const std::string& path, UnpublishedFile)
    : path_(path),
      mode_(StoreMode::kReadWrite),
      connection_(path, StoreMode::kReadWrite),
      db_(connection_.get()) {
  // Nobody else opens this file before it is whole, and a file cut short by
  // a crash here is never published: neither a journal nor syncs buy anything.
  Exec("PRAGMA journal_mode = OFF", "building a new store without a journal");
  Exec("PRAGMA synchronous = OFF", "building a new store without syncs");
  Exec("PRAGMA foreign_keys = ON", "enabling foreign keys");
  store_internal::RegisterRowDigestFunction(db_, path_);
  sql_stmt_begin_ = Prepare(store_sql::kBegin, "starting a transaction");
  sql_stmt_commit_ = Prepare(store_sql::kCommit, "committing a transaction");
  sql_stmt_rollback_ = Prepare(store_sql::kRollback, "rolling back a transaction");
  CreateOrUpgradeSchema();
  // Last: the file's header then says WAL, as EnableWriteAheadLog leaves it.
  if (JournalMode("PRAGMA journal_mode = WAL") != "wal") {
    throw StoreError("store '" + path_ + "': the file system refuses the write-ahead log");
  }
  fold_on_close_ = false;  // the log is empty; SQLite's close removes it
}

void SqliteArtifactStore::BuildUnpublishedFile(const std::string& path) {
  SqliteArtifactStore building(path, UnpublishedFile{});
}

std::string SqliteArtifactStore::JournalMode(const char* pragma, int* rc) {
  std::string mode;
  const int result = sqlite3_exec(
      db_, pragma,
      [](void* out, int, char** values, char**) {
        if (values[0] != nullptr) *static_cast<std::string*>(out) = values[0];
        return 0;
      },
      &mode, nullptr);
  if (rc != nullptr) {
    *rc = result;
  } else {
    CheckSqlite(db_, path_, result, "setting the journal mode");
  }
  return mode;
}

SqliteArtifactStore::SchemaState SqliteArtifactStore::ReadSchemaState() {
  // Raw calls: a file that is not SQLite fails here, and only here, with
  // NOTADB. One statement reads both values from one snapshot, so a process
  // creating the schema at the same moment cannot make a new file look foreign.
  sqlite3_stmt* statement = nullptr;
  int rc = sqlite3_prepare_v2(
      db_, "SELECT user_version, (SELECT count(*) FROM sqlite_master) FROM pragma_user_version", -1,
      &statement, nullptr);
  SchemaState state;
  if (rc == SQLITE_OK) {
    rc = sqlite3_step(statement);
    if (rc == SQLITE_ROW) {
      state.user_version = sqlite3_column_int(statement, 0);
      state.schema_objects = sqlite3_column_int64(statement, 1);
    }
  }
  sqlite3_finalize(statement);
  if ((rc & 0xff) == SQLITE_NOTADB) {
    throw StoreError("'" + path_ + "' is not an areagraph store (not an SQLite database)");
  }
  CheckSqlite(db_, path_, rc, "reading the schema version");
  return state;
}

void SqliteArtifactStore::CheckIsAreagraphStore(const SchemaState& state, StoreMode mode) {
  if (state.user_version > kStoreSchemaVersion) {
    throw StoreError("store '" + path_ + "' has schema version " +
                     std::to_string(state.user_version) + ", newer than this build's " +
                     std::to_string(kStoreSchemaVersion) + "; upgrade areagraph");
  }
  if (state.user_version > 0) return;
  // Version 0: a new file, or someone else's database that must stay untouched.
  if (state.schema_objects > 0) {
    throw StoreError("'" + path_ + "' is an SQLite database but not an areagraph store");
  }
  if (mode == StoreMode::kReadOnly && path_ != kMemoryStorePath) {
    throw StoreError("'" + path_ + "' is not an areagraph store (it is empty)");
  }
}

void SqliteArtifactStore::Exec(const char* sql, const std::string& action) {
  CheckSqlite(db_, path_, sqlite3_exec(db_, sql, nullptr, nullptr, nullptr), action);
}

void SqliteArtifactStore::EnableWriteAheadLog() {
  // Readers then never wait for writers, and a killed writer leaves a log
  // that the next opener rolls back or replays. Some file systems refuse WAL;
  // the store then keeps SQLite's rollback journal, which is as safe.
  // Switching needs a moment of exclusive access and SQLite does not wait for
  // it through the busy handler, so a process racing to create the same new
  // store retries here; once the file is in WAL mode this is a plain read.
  const auto give_up =
      std::chrono::steady_clock::now() + std::chrono::milliseconds(kStoreBusyTimeoutMs);
  while (true) {
    int rc = SQLITE_OK;
    const std::string mode = JournalMode("PRAGMA journal_mode = WAL", &rc);
    if ((rc & 0xff) != SQLITE_BUSY || std::chrono::steady_clock::now() > give_up) {
      CheckSqlite(db_, path_, rc, "switching to the write-ahead log");
      // With WAL, NORMAL syncs at checkpoints only: a killed process loses
      // nothing and the file cannot corrupt; a power cut may lose the last
      // commits. Saves an fsync per artifact, which serializes parallel runners.
      if (mode == "wal") Exec("PRAGMA synchronous = NORMAL", "setting the sync mode");
      return;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

void SqliteArtifactStore::CreateOrUpgradeSchema() {
  SqliteTransaction transaction = BeginTransaction();
  // Read again under the write lock: another process may have just created
  // or upgraded the schema. The version moves with the tables in this one
  // transaction, so a failed upgrade leaves the old store as it was.
  const int version = ReadSchemaState().user_version;
  if (version == 0) {
    CreateMapsTable();
    CreateArtifactsTable();
    CreateHeadsTable();
  }
  if (version < 2) Exec(store_sql::kCreateFailuresTable, "creating the failures table");
  if (version >= 1 && version < 3) {
    Exec(store_sql::kAddArtifactSummaryColumn, "adding the artifacts' summary column");
  }
  if (version < 4) Exec(store_sql::kCreateVersionsTable, "creating the versions table");
  if (version >= 1 && version < 5) {
    Exec(store_sql::kAddPayloadCodecColumn, "adding the artifacts' payload codec column");
    Exec(store_sql::kAddPayloadSizeColumn, "adding the artifacts' payload size column");
    Exec(store_sql::kFillPayloadSizes, "recording the payload sizes");
  }
  if (version >= 1 && version < 6) {
    Exec(store_sql::kAddRowDigestColumn, "adding the artifacts' row digest column");
    Exec(store_sql::kFillRowDigests, "recording the row digests");
  }
  if (version < kStoreSchemaVersion) {
    Exec(("PRAGMA user_version = " + std::to_string(kStoreSchemaVersion)).c_str(),
         "setting the schema version");
  }
  transaction.Commit();
  schema_version_ = kStoreSchemaVersion;
}

void SqliteArtifactStore::CreateMapsTable() {
  Exec(store_sql::kCreateMapsTable, "creating the maps table");
}

void SqliteArtifactStore::CreateArtifactsTable() {
  Exec(store_sql::kCreateArtifactsTable, "creating the artifacts table");
  Exec(store_sql::kCreateArtifactsByTimeIndex, "creating the artifacts index");
}

void SqliteArtifactStore::CreateHeadsTable() {
  Exec(store_sql::kCreateHeadsTable, "creating the heads table");
  Exec(store_sql::kCreateHeadsByArtifactIndex, "creating the heads index");
}

void SqliteArtifactStore::PrepareStatements() {
  sql_stmt_read_all_maps_ = Prepare(store_sql::kReadAllMaps, "reading the maps");
  sql_stmt_read_map_ = Prepare(store_sql::kReadMap, "reading a map");
  const int v = schema_version_;
  sql_stmt_read_artifact_ =
      Prepare(store_internal::ForSchema(
                  v, store_sql::kReadArtifact, store_sql::kReadArtifactBeforeSchema6,
                  store_sql::kReadArtifactBeforeSchema5, store_sql::kReadArtifactBeforeSchema3),
              "reading an artifact");
  sql_stmt_read_head_ =
      Prepare(store_internal::ForSchema(v, store_sql::kReadHead, store_sql::kReadHeadBeforeSchema6,
                                        store_sql::kReadHeadBeforeSchema5,
                                        store_sql::kReadHeadBeforeSchema3),
              "reading a head artifact");
  sql_stmt_read_artifact_summaries_ =
      Prepare(store_internal::ForSchema(v, store_sql::kReadArtifactSummaries,
                                        store_sql::kReadArtifactSummariesBeforeSchema6,
                                        store_sql::kReadArtifactSummariesBeforeSchema5,
                                        store_sql::kReadArtifactSummariesBeforeSchema3),
              "listing the artifacts of a map");
  sql_stmt_read_artifact_summary_ =
      Prepare(store_internal::ForSchema(v, store_sql::kReadArtifactSummary,
                                        store_sql::kReadArtifactSummaryBeforeSchema6,
                                        store_sql::kReadArtifactSummaryBeforeSchema5,
                                        store_sql::kReadArtifactSummaryBeforeSchema3),
              "reading an artifact");
  sql_stmt_read_artifact_ref_ = Prepare(store_sql::kReadArtifactRef, "finding an artifact");
  sql_stmt_read_artifact_id_ = Prepare(store_sql::kReadArtifactId, "finding an artifact");
  sql_stmt_upsert_map_ = Prepare(store_sql::kUpsertMap, "writing a map");
  if (HasRowDigests()) {  // an older store is only ever read
    sql_stmt_upsert_artifact_ = Prepare(store_sql::kUpsertArtifact, "writing an artifact");
  }
  sql_stmt_write_head_ = Prepare(store_sql::kWriteHead, "writing a head");
  sql_stmt_has_artifact_ = Prepare(store_sql::kHasArtifact, "looking up an artifact");
  sql_stmt_read_head_key_ = Prepare(store_sql::kReadHeadKey, "looking up a head");
  if (HasFailuresTable()) {
    sql_stmt_record_failure_ = Prepare(store_sql::kRecordFailure, "recording a failure");
    sql_stmt_clear_failure_ = Prepare(store_sql::kClearFailure, "clearing a failure");
    sql_stmt_read_failures_ = Prepare(store_sql::kReadFailures, "reading the failures");
  }
  PrepareVersionStatements();
}

LazyStatement SqliteArtifactStore::Prepare(const char* sql, const std::string& action) {
  return LazyStatement(db_, path_, sql, action);
}

SqliteTransaction SqliteArtifactStore::BeginTransaction() {
  return SqliteTransaction(db_, *sql_stmt_begin_, *sql_stmt_commit_, *sql_stmt_rollback_);
}

MapRecord SqliteArtifactStore::ReadMapRow(const SqliteStatement& statement) const {
  MapRecord map;
  map.id = statement.ColumnInt64(0, "maps.id");
  map.name = statement.ColumnText(1, "maps.name");
  map.source_path = statement.ColumnText(2, "maps.source_path");
  map.source_digest = statement.ColumnText(3, "maps.source_digest");
  return map;
}

ArtifactRecord SqliteArtifactStore::ReadArtifactRow(const SqliteStatement& statement,
                                                    const std::string& map_name,
                                                    bool with_payload) const {
  ArtifactRecord artifact;
  artifact.map_name = map_name;
  artifact.stage = statement.ColumnText(0, "artifacts.stage");
  artifact.cache_key = statement.ColumnText(1, "artifacts.cache_key");
  const std::string input_keys = statement.ColumnText(2, "artifacts.input_keys");
  artifact.input_keys = SplitLines(input_keys);
  artifact.options_text = statement.ColumnText(3, "artifacts.options");
  artifact.stage_version = static_cast<int>(statement.ColumnInt64(4, "artifacts.stage_version"));
  artifact.proto_type = statement.ColumnText(5, "artifacts.proto_type");
  artifact.payload_digest = statement.ColumnText(6, "artifacts.payload_digest");
  artifact.created_at = statement.ColumnText(7, "artifacts.created_at");
  artifact.elapsed_ms = statement.ColumnDouble(8, "artifacts.elapsed_ms");
  artifact.is_head = statement.ColumnInt64(9, "heads.artifact_id") != 0;
  artifact.summary_line = statement.ColumnText(10, "artifacts.summary");
  const auto corrupt = [&](const std::string& problem) {
    return StoreError("artifact " + ShortKey(artifact.cache_key) + " of map '" + map_name +
                      "' in store '" + path_ + "' is corrupt (" + problem + "); run ag-" +
                      artifact.stage + " --store " + path_ + " --map " + map_name +
                      " --force to recompute it");
  };
  const std::string row_digest = statement.ColumnText(11, "artifacts.row_digest");
  if (!row_digest.empty() &&  // empty in stores before schema 6
      ArtifactRowDigest({map_name, artifact.stage, artifact.cache_key, input_keys,
                         artifact.options_text, artifact.stage_version, artifact.proto_type,
                         artifact.payload_digest, artifact.summary_line, artifact.created_at}) !=
          row_digest) {
    throw StoreError("artifact " + ShortKey(artifact.cache_key) + " of map '" + map_name +
                     "' in store '" + path_ + "' is damaged (" +
                     store_internal::kRowDigestMismatch + "); ag-store verify --store " + path_ +
                     " lists the damage");
  }
  if (!with_payload) {
    artifact.payload_bytes = statement.ColumnInt64(12, "artifacts.payload_size");
    return artifact;
  }
  try {
    artifact.payload = DecodePayload(statement.ColumnBlobView(12, "artifacts.payload"),
                                     statement.ColumnInt64(13, "artifacts.payload_codec"));
  } catch (const StoreError& error) {
    throw corrupt(error.what());
  }
  artifact.payload_bytes = static_cast<int64_t>(artifact.payload.size());
  if (Sha256Hex(artifact.payload) != artifact.payload_digest) {
    throw corrupt("payload digest mismatch");
  }
  return artifact;
}

std::vector<MapRecord> SqliteArtifactStore::ReadAllMaps() {
  StatementUse use(*sql_stmt_read_all_maps_);
  std::vector<MapRecord> maps;
  while (sql_stmt_read_all_maps_->Step()) maps.push_back(ReadMapRow(*sql_stmt_read_all_maps_));
  return maps;
}

std::optional<MapRecord> SqliteArtifactStore::ReadMap(const std::string& map_name) {
  StatementUse use(*sql_stmt_read_map_);
  sql_stmt_read_map_->BindText(1, map_name);
  if (!sql_stmt_read_map_->Step()) return std::nullopt;
  return ReadMapRow(*sql_stmt_read_map_);
}

std::optional<ArtifactRecord> SqliteArtifactStore::ReadArtifact(const std::string& map_name,
                                                                const std::string& cache_key) {
  StatementUse use(*sql_stmt_read_artifact_);
  sql_stmt_read_artifact_->BindText(1, map_name);
  sql_stmt_read_artifact_->BindText(2, cache_key);
  if (!sql_stmt_read_artifact_->Step()) return std::nullopt;
  return ReadArtifactRow(*sql_stmt_read_artifact_, map_name, /*with_payload=*/true);
}

std::optional<ArtifactRecord> SqliteArtifactStore::ReadHead(const std::string& map_name,
                                                            const std::string& stage) {
  StatementUse use(*sql_stmt_read_head_);
  sql_stmt_read_head_->BindText(1, map_name);
  sql_stmt_read_head_->BindText(2, stage);
  if (!sql_stmt_read_head_->Step()) return std::nullopt;
  return ReadArtifactRow(*sql_stmt_read_head_, map_name, /*with_payload=*/true);
}

std::vector<ArtifactRecord> SqliteArtifactStore::ReadArtifactSummaries(
    const std::string& map_name) {
  SqliteStatement& statement = *sql_stmt_read_artifact_summaries_;
  StatementUse use(statement);
  statement.BindText(1, map_name);
  std::vector<ArtifactRecord> summaries;
  while (statement.Step()) {
    summaries.push_back(ReadArtifactRow(statement, map_name, /*with_payload=*/false));
  }
  return summaries;
}

std::optional<ArtifactRecord> SqliteArtifactStore::ReadArtifactSummary(
    const std::string& map_name, const std::string& cache_key) {
  SqliteStatement& statement = *sql_stmt_read_artifact_summary_;
  StatementUse use(statement);
  statement.BindText(1, map_name);
  statement.BindText(2, cache_key);
  if (!statement.Step()) return std::nullopt;
  return ReadArtifactRow(statement, map_name, /*with_payload=*/false);
}

void SqliteArtifactStore::WriteArtifact(const NewArtifact& artifact) {
  if (!sql_stmt_upsert_artifact_) {
    throw StoreError("store '" + path_ + "' has schema version " + std::to_string(schema_version_) +
                     "; open it for writing to upgrade it");
  }
  for (const std::string& key : artifact.input_keys) {
    if (key.find('\n') != std::string::npos) {
      throw StoreError("input key of a " + artifact.stage + " artifact contains a line break");
    }
  }
  // Hashing before the transaction keeps the write lock short. A payload
  // encoded by the caller is used where it is, not copied (tens of MB on big
  // maps).
  std::optional<EncodedPayload> encoded_here;
  if (!artifact.encoded_payload) encoded_here = EncodeRawPayload(artifact.payload);
  const EncodedPayload& payload =
      artifact.encoded_payload ? *artifact.encoded_payload : *encoded_here;
  const std::string created_at = StoreTimeNow();
  const std::string input_keys = JoinLines(artifact.input_keys);
  const std::string row_digest =
      ArtifactRowDigest({artifact.map_name, artifact.stage, artifact.cache_key, input_keys,
                         artifact.options_text, artifact.stage_version, artifact.proto_type,
                         payload.digest, artifact.summary_line, created_at});
  SqliteTransaction transaction = BeginTransaction();

  int64_t map_id = 0;
  {
    StatementUse use(*sql_stmt_upsert_map_);
    sql_stmt_upsert_map_->BindText(1, artifact.map_name);
    if (artifact.source_path) sql_stmt_upsert_map_->BindText(2, *artifact.source_path);
    if (artifact.source_digest) sql_stmt_upsert_map_->BindText(3, *artifact.source_digest);
    sql_stmt_upsert_map_->Step();
  }
  {
    StatementUse use(*sql_stmt_read_map_);
    sql_stmt_read_map_->BindText(1, artifact.map_name);
    sql_stmt_read_map_->Step();
    map_id = sql_stmt_read_map_->ColumnInt64(0, "maps.id");
  }
  {
    SqliteStatement& insert = *sql_stmt_upsert_artifact_;
    StatementUse use(insert);
    insert.BindInt64(1, map_id);
    insert.BindText(2, artifact.stage);
    insert.BindText(3, artifact.cache_key);
    insert.BindText(4, input_keys);
    insert.BindText(5, artifact.options_text);
    insert.BindInt64(6, artifact.stage_version);
    insert.BindText(7, artifact.proto_type);
    insert.BindBlobUncopied(8, payload.frame);  // `payload` outlives `use`
    insert.BindText(9, payload.digest);
    insert.BindDouble(10, artifact.elapsed_ms);
    insert.BindText(11, artifact.summary_line);
    insert.BindInt64(12, static_cast<int64_t>(PayloadCodec::kZstd));
    insert.BindInt64(13, payload.raw_bytes);
    insert.BindText(14, created_at);
    insert.BindText(15, row_digest);
    insert.Step();
  }
  int64_t artifact_id = 0;
  {
    StatementUse use(*sql_stmt_read_artifact_id_);
    sql_stmt_read_artifact_id_->BindInt64(1, map_id);
    sql_stmt_read_artifact_id_->BindText(2, artifact.cache_key);
    sql_stmt_read_artifact_id_->Step();
    artifact_id = sql_stmt_read_artifact_id_->ColumnInt64(0, "artifacts.id");
  }
  WriteHead(map_id, artifact.stage, artifact_id);
  if (artifact.version) InsertVersion(map_id, artifact);
  transaction.Commit();
}

void SqliteArtifactStore::UpdateHead(const std::string& map_name, const std::string& cache_key) {
  SqliteTransaction transaction = BeginTransaction();
  int64_t artifact_id = 0, map_id = 0;
  std::string stage;
  {
    SqliteStatement& find = *sql_stmt_read_artifact_ref_;
    StatementUse use(find);
    find.BindText(1, map_name);
    find.BindText(2, cache_key);
    if (!find.Step()) {
      throw StoreError("map '" + map_name + "' has no artifact " + ShortKey(cache_key) +
                       " in store '" + path_ + "'");
    }
    artifact_id = find.ColumnInt64(0, "artifacts.id");
    map_id = find.ColumnInt64(1, "artifacts.map_id");
    stage = find.ColumnText(2, "artifacts.stage");
  }
  WriteHead(map_id, stage, artifact_id);
  transaction.Commit();
}

void SqliteArtifactStore::WriteHead(int64_t map_id, const std::string& stage, int64_t artifact_id) {
  StatementUse use(*sql_stmt_write_head_);
  sql_stmt_write_head_->BindInt64(1, map_id);
  sql_stmt_write_head_->BindText(2, stage);
  sql_stmt_write_head_->BindInt64(3, artifact_id);
  sql_stmt_write_head_->Step();
}

bool SqliteArtifactStore::HasArtifact(const std::string& map_name, const std::string& cache_key) {
  StatementUse use(*sql_stmt_has_artifact_);
  sql_stmt_has_artifact_->BindText(1, map_name);
  sql_stmt_has_artifact_->BindText(2, cache_key);
  return sql_stmt_has_artifact_->Step();
}

std::optional<std::string> SqliteArtifactStore::ReadHeadKey(const std::string& map_name,
                                                            const std::string& stage) {
  StatementUse use(*sql_stmt_read_head_key_);
  sql_stmt_read_head_key_->BindText(1, map_name);
  sql_stmt_read_head_key_->BindText(2, stage);
  if (!sql_stmt_read_head_key_->Step()) return std::nullopt;
  return sql_stmt_read_head_key_->ColumnText(0, "artifacts.cache_key");
}

void SqliteArtifactStore::RecordFailure(const FailureRecord& failure) {
  if (!HasFailuresTable()) {
    throw StoreError("store '" + path_ + "' has schema version " + std::to_string(schema_version_) +
                     " without failures; open it for writing to upgrade it");
  }
  // One statement: its own transaction, waiting on the busy timeout.
  StatementUse use(*sql_stmt_record_failure_);
  sql_stmt_record_failure_->BindText(1, failure.map_name);
  sql_stmt_record_failure_->BindText(2, failure.stage);
  sql_stmt_record_failure_->BindText(3, failure.message);
  sql_stmt_record_failure_->BindText(4, failure.source_path);
  sql_stmt_record_failure_->Step();
}

void SqliteArtifactStore::ClearFailure(const std::string& map_name) {
  if (!HasFailuresTable()) return;  // nothing can be recorded, so nothing to clear
  StatementUse use(*sql_stmt_clear_failure_);
  sql_stmt_clear_failure_->BindText(1, map_name);
  sql_stmt_clear_failure_->Step();
}

std::vector<FailureRecord> SqliteArtifactStore::ReadFailures() {
  std::vector<FailureRecord> failures;
  if (!HasFailuresTable()) return failures;
  SqliteStatement& statement = *sql_stmt_read_failures_;
  StatementUse use(statement);
  while (statement.Step()) failures.push_back(store_internal::ReadFailureRow(statement));
  return failures;
}

FailureRecord store_internal::ReadFailureRow(const SqliteStatement& statement) {
  FailureRecord failure;
  failure.map_name = statement.ColumnText(0, "failures.map_name");
  failure.stage = statement.ColumnText(1, "failures.stage");
  failure.message = statement.ColumnText(2, "failures.message");
  failure.source_path = statement.ColumnText(3, "failures.source_path");
  failure.failed_at = statement.ColumnText(4, "failures.failed_at");
  return failure;
}

std::unique_ptr<ArtifactStore> OpenArtifactStore(const std::string& path, StoreMode mode) {
  if (IsCollectionIndex(path)) return OpenCollectionIndexStore(path, mode);
  if (mode == StoreMode::kReadWrite) store_internal::CreateMissingStoreFile(path);
  return std::make_unique<SqliteArtifactStore>(path, mode);
}

}  // namespace areagraph
