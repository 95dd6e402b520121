// What keeps a store whole beyond single writes: SQLite's structure checks
// (verify, merge), payload checks of merged artifacts, folding the
// write-ahead log into the file, and online backups.

#include <sqlite3.h>

#include <cstdio>
#include <filesystem>

#include "common/error.h"
#include "common/text.h"
#include "store/digest.h"
#include "store/payload_codec.h"
#include "store/protobuf_wire.h"
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
      if (row != "ok") findings.push_back(row);
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
  throw StoreError("store '" + path + "' is damaged: artifact " +
                   ShortKey(find.ColumnText(2, "artifacts.cache_key")) + " of map '" +
                   find.ColumnText(0, "maps.name") + "' (" + find.ColumnText(1, "artifacts.stage") +
                   ") has a corrupt payload (" + find.ColumnText(3, "problem") +
                   "); nothing was merged from it (ag-store verify --store " + path +
                   " lists the problems)");
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
  CheckSqlite(db_, path_, rc, "folding the write-ahead log into the store file");
  return true;
}

void SqliteArtifactStore::LeaveWriteAheadLogOnClose() {
  if (path_ == kMemoryStorePath || mode_ != StoreMode::kReadWrite) return;
  // SQLite's own close would fold the log when this is its last connection.
  CheckSqlite(db_, path_, sqlite3_db_config(db_, SQLITE_DBCONFIG_NO_CKPT_ON_CLOSE, 1, nullptr),
              "keeping the write-ahead log on close");
  fold_on_close_ = false;
}

SqliteArtifactStore::~SqliteArtifactStore() {
  if (!fold_on_close_) return;
  try {
    FoldWriteAheadLog();
  } catch (const StoreError&) {
    // The log stays; SQLite replays it on the next open, so nothing is lost.
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
