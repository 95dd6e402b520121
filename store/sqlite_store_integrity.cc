// What keeps a store whole beyond single writes: SQLite's structure checks
// (verify, merge), payload checks of merged artifacts, folding the
// write-ahead log into the file, and online backups.

#include <sqlite3.h>

#include <cstdio>
#include <filesystem>
#include <mutex>
#include <optional>

#include "common/error.h"
#include "common/text.h"
#include "store/digest.h"
#include "store/payload_codec.h"
#include "store/protobuf_wire.h"
#include "store/row_digest.h"
#include "store/sqlite_artifact_store.h"
#include "store/sqlite_store_maintenance_sql.h"

namespace areagraph {

namespace store_internal {

std::optional<std::string> PayloadProblem(std::string_view stored, int64_t codec,
                                          std::string_view digest) {
  std::string payload;
  try {
    payload = DecodePayload(stored, codec);
  } catch (const StoreError& error) {
    return std::string(error.what());
  }
  if (Sha256Hex(payload) != digest) return "payload digest mismatch";
  if (!IsWellFormedProtobuf(payload)) return "payload is not protobuf wire format";
  return std::nullopt;
}

}  // namespace store_internal

namespace {

std::string_view TextValue(sqlite3_value* value) {
  const auto* text = reinterpret_cast<const char*>(sqlite3_value_text(value));
  return std::string_view(text == nullptr ? "" : text,
                          static_cast<size_t>(sqlite3_value_bytes(value)));
}

// SQL function ag_row_digest(...): ArtifactRowDigest of its ten arguments.
void RowDigestFunction(sqlite3_context* context, int, sqlite3_value** values) {
  const std::string digest = ArtifactRowDigest(
      {TextValue(values[0]), TextValue(values[1]), TextValue(values[2]), TextValue(values[3]),
       TextValue(values[4]), sqlite3_value_int64(values[5]), TextValue(values[6]),
       TextValue(values[7]), TextValue(values[8]), TextValue(values[9])});
  sqlite3_result_text(context, digest.c_str(), static_cast<int>(digest.size()), SQLITE_TRANSIENT);
}

// SQL function ag_payload_problem(payload, codec, digest): NULL or the problem.
void PayloadProblemFunction(sqlite3_context* context, int, sqlite3_value** values) {
  const auto* payload = static_cast<const char*>(sqlite3_value_blob(values[0]));
  const int payload_bytes = sqlite3_value_bytes(values[0]);
  const int64_t codec = sqlite3_value_int64(values[1]);
  const auto* digest = reinterpret_cast<const char*>(sqlite3_value_text(values[2]));
  const int digest_bytes = sqlite3_value_bytes(values[2]);
  const std::optional<std::string> problem = store_internal::PayloadProblem(
      std::string_view(payload == nullptr ? "" : payload, static_cast<size_t>(payload_bytes)),
      codec, std::string_view(digest == nullptr ? "" : digest, static_cast<size_t>(digest_bytes)));
  if (!problem) return sqlite3_result_null(context);
  sqlite3_result_text(context, problem->c_str(), static_cast<int>(problem->size()),
                      SQLITE_TRANSIENT);
}

// Throws the refusal of merge source `path` for the artifact on `row`
// (columns: map name, stage, key) and what is wrong with it.
[[noreturn]] void RefuseDamagedMergeSource(const std::string& path, const SqliteStatement& row,
                                           const std::string& what) {
  throw StoreError("store '" + path + "' is damaged: artifact " +
                   ShortKey(row.ColumnText(2, "artifacts.cache_key")) + " of map '" +
                   row.ColumnText(0, "maps.name") + "' (" + row.ColumnText(1, "artifacts.stage") +
                   ") " + what + "; nothing was merged from it (ag-store verify --store " + path +
                   " lists the problems)");
}

// Closes a connection that is not a store's own (a backup's destination).
class OwnedConnection {
 public:
  ~OwnedConnection() { sqlite3_close_v2(db); }
  sqlite3* db = nullptr;
};

}  // namespace

std::vector<std::string> SqliteArtifactStore::CheckStructure(const char* schema,
                                                             StructureCheck structure) {
  char sql[64];
  std::snprintf(
      sql, sizeof(sql),
      structure == StructureCheck::kFull ? store_sql::kIntegrityCheckOf : store_sql::kQuickCheckOf,
      schema);
  SqliteStatement check(db_, path_, sql, std::string("checking the SQLite structure of ") + schema);
  StatementUse use(check);
  std::vector<std::string> findings;
  try {
    while (check.Step()) {
      const std::string row = check.ColumnText(0, "integrity_check");
      if (row == "ok") continue;
      // One row may hold several findings, a line each (the b-tree checks').
      for (const std::string& line : store_internal::SplitLines(row)) {
        if (!line.empty()) findings.push_back(line);
      }
    }
  } catch (const StoreError&) {
    // Damage can stop the check itself; that is its finding.
    const int code = sqlite3_errcode(db_) & 0xff;
    if (code != SQLITE_CORRUPT && code != SQLITE_NOTADB) throw;
    findings.push_back(std::string(sqlite3_errstr(code)) + " (the check could not finish)");
  }
  return findings;
}

void SqliteArtifactStore::CheckMergeSourcePayloads(const std::string& path, int source_version) {
  CheckSqlite(
      db_, path_,
      sqlite3_create_function_v2(db_, "ag_payload_problem", 3,
                                 SQLITE_UTF8 | SQLITE_DETERMINISTIC | SQLITE_DIRECTONLY, nullptr,
                                 PayloadProblemFunction, nullptr, nullptr, nullptr),
      "registering the payload check");
  SqliteStatement find(db_, path_,
                       source_version >= 5 ? store_sql::kFindDamagedMergePayload
                                           : store_sql::kFindDamagedMergePayloadBeforeSchema5,
                       "merging: checking the payloads of '" + path + "'");
  StatementUse use(find);
  if (!find.Step()) return;
  RefuseDamagedMergeSource(path, find,
                           "has a corrupt payload (" + find.ColumnText(3, "problem") + ")");
}

void store_internal::RegisterRowDigestFunction(sqlite3* db, const std::string& path) {
  CheckSqlite(db, path,
              sqlite3_create_function_v2(db, "ag_row_digest", 10,
                                         SQLITE_UTF8 | SQLITE_DETERMINISTIC | SQLITE_DIRECTONLY,
                                         nullptr, RowDigestFunction, nullptr, nullptr, nullptr),
              "registering the row digest");
}

void SqliteArtifactStore::CheckMergeSourceRows(const std::string& path, int source_version) {
  if (source_version < 6) return;  // no row digests to check
  SqliteStatement find(db_, path_, store_sql::kFindDamagedMergeRow,
                       "merging: checking the rows of '" + path + "'");
  StatementUse use(find);
  if (!find.Step()) return;
  RefuseDamagedMergeSource(
      path, find, std::string("has a damaged row (") + store_internal::kRowDigestMismatch + ")");
}

bool HasWriteAheadLog(const std::string& path) {
  if (path == kMemoryStorePath) return false;
  std::error_code missing;
  const uintmax_t bytes = std::filesystem::file_size(path + "-wal", missing);
  return !missing && bytes > 0;
}

bool SqliteArtifactStore::FoldWriteAheadLog() {
  if (path_ == kMemoryStorePath) return true;  // no file, no log
  if (mode_ != StoreMode::kReadWrite) return false;
  // Waiting here could hold a closing tool for the whole busy timeout while
  // others work; whoever closes last folds the log instead.
  sqlite3_busy_timeout(db_, 0);
  const int rc =
      sqlite3_wal_checkpoint_v2(db_, "main", SQLITE_CHECKPOINT_TRUNCATE, nullptr, nullptr);
  sqlite3_busy_timeout(db_, kStoreBusyTimeoutMs);
  if ((rc & 0xff) == SQLITE_BUSY || (rc & 0xff) == SQLITE_LOCKED) return false;
  if (rc != SQLITE_OK) throw StoreError(UnfoldedLogMessage(path_, SqliteReason(db_, rc)));
  return true;
}

void SqliteArtifactStore::LeaveWriteAheadLogOnClose() {
  if (path_ == kMemoryStorePath || mode_ != StoreMode::kReadWrite) return;
  // SQLite's own close would fold the log when this is its last connection.
  CheckSqlite(db_, path_, sqlite3_db_config(db_, SQLITE_DBCONFIG_NO_CKPT_ON_CLOSE, 1, nullptr),
              "keeping the write-ahead log on close");
  fold_on_close_ = false;
}

namespace {

std::mutex unfolded_log_mutex;
std::optional<std::string> unfolded_log_problem;

}  // namespace

std::string UnfoldedLogMessage(const std::string& path, const std::string& why) {
  return "the write-ahead log could not be folded into store '" + path + "' (" + why + "): '" +
         path + "-wal' holds commits that '" + path +
         "' alone lacks; keep the two together until a later tool folds it (ag-store verify "
         "does, once there is room)";
}

std::optional<std::string> TakeUnfoldedLogProblem() {
  const std::lock_guard<std::mutex> lock(unfolded_log_mutex);
  std::optional<std::string> problem;
  problem.swap(unfolded_log_problem);
  return problem;
}

SqliteArtifactStore::~SqliteArtifactStore() {
  if (!fold_on_close_) return;
  try {
    FoldWriteAheadLog();
  } catch (const StoreError& error) {
    // The log stays and SQLite replays it on the next open, so nothing is
    // lost; but the file alone is not the store until then.
    const std::lock_guard<std::mutex> lock(unfolded_log_mutex);
    unfolded_log_problem = error.what();
  }
}

void SqliteArtifactStore::BackupTo(const std::string& path) {
  OwnedConnection out;
  CheckSqlite(
      out.db, path,
      sqlite3_open_v2(path.c_str(), &out.db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr),
      "creating the backup");
  sqlite3_backup* backup = sqlite3_backup_init(out.db, "main", db_, "main");
  if (backup == nullptr) CheckSqlite(out.db, path, sqlite3_errcode(out.db), "starting the backup");
  // All pages in one step: one read snapshot of this store, which under WAL
  // never blocks its writers.
  const int step = sqlite3_backup_step(backup, -1);
  const int finish = sqlite3_backup_finish(backup);
  if (step != SQLITE_DONE) CheckSqlite(out.db, path, step, "copying '" + path_ + "'");
  CheckSqlite(out.db, path, finish, "finishing the backup");
  CheckSqlite(out.db, path,
              sqlite3_exec(out.db, "PRAGMA wal_checkpoint(TRUNCATE)", nullptr, nullptr, nullptr),
              "folding the backup's log into its file");
  CheckSqlite(out.db, path, sqlite3_close(out.db), "closing the backup");
  out.db = nullptr;
}

}  // namespace areagraph
