// Maintenance of the SQLite store: Verify, CollectGarbage, MergeFrom and
// VacuumArtifactStore (ag-store).

#include <sqlite3.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <unordered_set>

#include "common/error.h"
#include "common/text.h"
#include "store/collection_index.h"
#include "store/digest.h"
#include "store/payload_codec.h"
#include "store/protobuf_wire.h"
#include "store/row_digest.h"
#include "store/sqlite_artifact_store.h"
#include "store/sqlite_connection.h"
#include "store/sqlite_store_maintenance_sql.h"
#include "store/store_maintenance.h"

namespace areagraph {

using store_internal::SplitLines;

namespace {

// One read snapshot over several statements, so counts and rows agree while
// other processes write. Ends (COMMIT of nothing) when the scope ends.
class ReadSnapshot {
 public:
  ReadSnapshot(sqlite3* db, const std::string& path) : db_(db) {
    CheckSqlite(db, path, sqlite3_exec(db, store_sql::kBeginRead, nullptr, nullptr, nullptr),
                "starting a read");
  }
  ~ReadSnapshot() { sqlite3_exec(db_, store_sql::kEndRead, nullptr, nullptr, nullptr); }
  ReadSnapshot(const ReadSnapshot&) = delete;
  ReadSnapshot& operator=(const ReadSnapshot&) = delete;

 private:
  sqlite3* db_;
};

// Detaches the merge source when the merge ends, also on an error (after the
// transaction has rolled back, since this is constructed before it).
class MergeSourceAttachment {
 public:
  explicit MergeSourceAttachment(sqlite3* db) : db_(db) {}
  ~MergeSourceAttachment() {
    sqlite3_exec(db_, store_sql::kDetachMergeSource, nullptr, nullptr, nullptr);
  }
  MergeSourceAttachment(const MergeSourceAttachment&) = delete;
  MergeSourceAttachment& operator=(const MergeSourceAttachment&) = delete;

 private:
  sqlite3* db_;
};

// Runs one statement to its end and returns how many rows it changed.
int64_t Run(sqlite3* db, const std::string& store_path, const char* sql,
            const std::string& action) {
  SqliteStatement statement(db, store_path, sql, action);
  StatementUse use(statement);
  while (statement.Step()) {
  }
  return sqlite3_changes(db);
}

}  // namespace

std::vector<VerifyProblem> SqliteArtifactStore::Verify(
    const std::vector<std::string>& file_input_stages,
    const std::function<void(int64_t, int64_t)>& progress, StructureCheck structure) {
  std::vector<VerifyProblem> problems;
  try {
    ReadSnapshot snapshot(db_, path_);
    for (const std::string& finding : CheckStructure("main", structure)) {
      problems.push_back({"", "", "", "SQLite: " + finding});
    }
    CheckArtifacts(file_input_stages, progress, problems);
    FindBrokenHeads(problems);
  } catch (const StoreError& error) {
    // Damage that stops the reading itself ("database disk image is malformed").
    problems.push_back(
        {"", "", "", std::string("cannot read the store to the end: ") + error.what()});
  }
  return problems;
}

void SqliteArtifactStore::CheckArtifacts(const std::vector<std::string>& file_input_stages,
                                         const std::function<void(int64_t, int64_t)>& progress,
                                         std::vector<VerifyProblem>& problems) {
  int64_t total = 0;
  {
    SqliteStatement count(db_, path_, store_sql::kCountArtifacts, "counting the artifacts");
    StatementUse use(count);
    count.Step();
    total = count.ColumnInt64(0, "count(*)");
  }
  SqliteStatement rows(db_, path_,
                       HasRowDigests()      ? store_sql::kVerifyArtifacts
                       : HasPayloadCodecs() ? store_sql::kVerifyArtifactsBeforeSchema6
                                            : store_sql::kVerifyArtifactsBeforeSchema5,
                       "verifying the artifacts");
  StatementUse use(rows);
  int64_t done = 0;
  while (rows.Step()) {  // one payload in memory at a time
    CheckArtifactRow(rows, file_input_stages, problems);
    ++done;
    if (progress) progress(done, std::max(total, done));
  }
}

void SqliteArtifactStore::CheckArtifactRow(SqliteStatement& row,
                                           const std::vector<std::string>& file_input_stages,
                                           std::vector<VerifyProblem>& problems) {
  VerifyProblem found;
  const auto report = [&](const std::string& problem) {
    found.problem = problem;
    problems.push_back(found);
  };
  try {
    const int64_t id = row.ColumnInt64(0, "artifacts.id");
    const int64_t map_id = row.ColumnInt64(1, "artifacts.map_id");
    found.map_name = row.ColumnText(3, "maps.name");
    found.stage = row.ColumnText(4, "artifacts.stage");
    found.cache_key = row.ColumnText(5, "artifacts.cache_key");
    if (row.ColumnInt64(2, "maps.id") == 0) {
      return report("artifact row " + std::to_string(id) + " belongs to no map");
    }
    const std::string row_digest = row.ColumnText(15, "artifacts.row_digest");
    if (!row_digest.empty() &&
        ArtifactRowDigest(
            {found.map_name, found.stage, found.cache_key,
             row.ColumnText(6, "artifacts.input_keys"), row.ColumnText(10, "artifacts.options"),
             row.ColumnInt64(11, "artifacts.stage_version"),
             row.ColumnText(12, "artifacts.proto_type"),
             row.ColumnText(7, "artifacts.payload_digest"), row.ColumnText(13, "artifacts.summary"),
             row.ColumnText(14, "artifacts.created_at")}) != row_digest) {
      report(store_internal::kRowDigestMismatch);  // and the payload is checked too
    }
    const std::optional<std::string> damage = store_internal::PayloadProblem(
        row.ColumnBlobView(8, "artifacts.payload"), row.ColumnInt64(9, "artifacts.payload_codec"),
        row.ColumnText(7, "artifacts.payload_digest"));
    if (damage && damage->rfind("payload is not protobuf", 0) != 0) {
      return report(*damage + " (corrupt); recompute it with ag-" + found.stage + " --force");
    }
    if (damage) return report(*damage);
    if (std::find(file_input_stages.begin(), file_input_stages.end(), found.stage) !=
        file_input_stages.end()) {
      return;  // its input is the digest of a file, not an artifact
    }
    for (const std::string& key : SplitLines(row.ColumnText(6, "artifacts.input_keys"))) {
      StatementUse use_lookup(*sql_stmt_read_artifact_id_);
      sql_stmt_read_artifact_id_->BindInt64(1, map_id);
      sql_stmt_read_artifact_id_->BindText(2, key);
      if (!sql_stmt_read_artifact_id_->Step()) {
        report("input " + ShortKey(key) + " is not an artifact of the map");
      }
    }
  } catch (const StoreError& error) {
    report(error.what());  // a hand-edited row: reported, and the check goes on
  }
}

void SqliteArtifactStore::FindBrokenHeads(std::vector<VerifyProblem>& problems) {
  SqliteStatement heads(db_, path_, store_sql::kFindBrokenHeads, "checking the heads");
  StatementUse use(heads);
  while (heads.Step()) {
    VerifyProblem problem;
    problem.map_name = heads.ColumnText(0, "maps.name");
    problem.stage = heads.ColumnText(1, "heads.stage");
    problem.cache_key = heads.ColumnText(2, "artifacts.cache_key");
    problem.problem = heads.ColumnText(3, "problem");
    problems.push_back(std::move(problem));
  }
}

MaintenanceCounts SqliteArtifactStore::CollectGarbage() {
  MaintenanceCounts counts;
  SqliteTransaction transaction = BeginTransaction();
  // Walk from the heads through input keys; ids only, so memory stays small.
  std::unordered_set<int64_t> kept;
  std::vector<int64_t> to_visit;
  {
    SqliteStatement heads(db_, path_, store_sql::kReadHeadArtifactIds, "reading the heads");
    StatementUse use(heads);
    while (heads.Step()) {
      const int64_t id = heads.ColumnInt64(0, "heads.artifact_id");
      if (kept.insert(id).second) to_visit.push_back(id);
    }
  }
  SqliteStatement inputs(db_, path_, store_sql::kReadArtifactInputs, "reading input keys");
  while (!to_visit.empty()) {
    const int64_t id = to_visit.back();
    to_visit.pop_back();
    int64_t map_id = 0;
    std::vector<std::string> keys;
    {
      StatementUse use(inputs);
      inputs.BindInt64(1, id);
      if (!inputs.Step()) continue;  // a broken head; verify reports it
      map_id = inputs.ColumnInt64(0, "artifacts.map_id");
      keys = SplitLines(inputs.ColumnText(1, "artifacts.input_keys"));
    }
    for (const std::string& key : keys) {
      StatementUse use(*sql_stmt_read_artifact_id_);
      sql_stmt_read_artifact_id_->BindInt64(1, map_id);
      sql_stmt_read_artifact_id_->BindText(2, key);
      if (!sql_stmt_read_artifact_id_->Step()) continue;  // e.g. an import's file digest
      const int64_t input_id = sql_stmt_read_artifact_id_->ColumnInt64(0, "artifacts.id");
      if (kept.insert(input_id).second) to_visit.push_back(input_id);
    }
  }
  std::vector<int64_t> garbage;
  {
    SqliteStatement sizes(db_, path_, store_sql::kListArtifactSizes, "listing the artifacts");
    StatementUse use(sizes);
    while (sizes.Step()) {
      const int64_t id = sizes.ColumnInt64(0, "artifacts.id");
      if (kept.count(id) > 0) continue;
      garbage.push_back(id);
      counts.payload_bytes += sizes.ColumnInt64(1, "artifacts.payload_size");
    }
  }
  SqliteStatement erase(db_, path_, store_sql::kDeleteArtifact, "deleting an artifact");
  for (const int64_t id : garbage) {
    StatementUse use(erase);
    erase.BindInt64(1, id);
    erase.Step();
  }
  counts.artifacts = static_cast<int64_t>(garbage.size());
  counts.maps = Run(db_, path_, store_sql::kDeleteEmptyMaps, "deleting empty maps");
  transaction.Commit();
  return counts;
}

void SqliteArtifactStore::CheckCanMergeFrom(const std::string& path) {
  if (path == kMemoryStorePath) {
    throw StoreError("cannot merge from '" + path + "': it is always a new, empty store");
  }
  std::error_code ignored;
  if (path_ != kMemoryStorePath && std::filesystem::equivalent(path, path_, ignored)) {
    throw StoreError("cannot merge store '" + path + "' into itself");
  }
  if (IsCollectionIndex(path)) {
    throw StoreError("cannot merge collection index '" + path +
                     "' as a store: merge the shard stores it names");
  }
  // The usual open checks: exists, is SQLite, is ours, is not newer.
  OpenArtifactStore(path, StoreMode::kReadOnly);
}

MaintenanceCounts SqliteArtifactStore::MergeFrom(const std::string& path) {
  CheckCanMergeFrom(path);
  {
    SqliteStatement attach(db_, path_, store_sql::kAttachMergeSource,
                           "attaching store '" + path + "'");
    StatementUse use(attach);
    attach.BindText(1, StoreUri(path, ChooseReadAccess(path)));
    attach.Step();
  }
  MergeSourceAttachment attachment(db_);
  int64_t source_version = 0;
  {
    SqliteStatement version(db_, path_, store_sql::kReadMergeSourceVersion,
                            "reading the schema version of '" + path + "'");
    StatementUse use(version);
    version.Step();
    source_version = version.ColumnInt64(0, "user_version");
  }
  if (source_version < 1 || source_version > kStoreSchemaVersion) {  // changed since checked
    throw StoreError("store '" + path + "' changed while being merged; try again");
  }
  // The full check: an index out of step with its table (a damaged key or
  // name) would otherwise steer the lookups below to the wrong rows.
  const std::vector<std::string> findings = CheckStructure("merge_source", StructureCheck::kFull);
  if (!findings.empty()) {
    throw StoreError("store '" + path + "' is damaged (SQLite: " + findings.front() +
                     "); nothing was merged from it (ag-store verify --store " + path +
                     " lists the problems)");
  }
  return CopyFromMergeSource(path, static_cast<int>(source_version));
}

MaintenanceCounts SqliteArtifactStore::CopyFromMergeSource(const std::string& path,
                                                           int source_version) {
  MaintenanceCounts counts;
  SqliteTransaction transaction = BeginTransaction();
  const auto run = [this](const char* sql, const char* action) {
    return Run(db_, path_, sql, std::string("merging: ") + action);
  };
  counts.maps = run(store_sql::kMergeMaps, "copying maps");
  {
    SqliteStatement count(db_, path_,
                          source_version >= 5 ? store_sql::kCountNewArtifacts
                                              : store_sql::kCountNewArtifactsBeforeSchema5,
                          "merging: counting");
    StatementUse use(count);
    count.Step();
    counts.payload_bytes = count.ColumnInt64(1, "sum(length(payload))");
  }
  // Under the write lock: what is copied next.
  CheckMergeSourceRows(path, source_version);
  CheckMergeSourcePayloads(path, source_version);
  counts.artifacts =
      run(store_internal::ForSchema(
              source_version, store_sql::kMergeArtifacts, store_sql::kMergeArtifactsBeforeSchema6,
              store_sql::kMergeArtifactsBeforeSchema5, store_sql::kMergeArtifactsBeforeSchema3),
          "copying artifacts");
  run(store_sql::kCreateWinningHeads, "comparing heads");
  run(store_sql::kFindWinningHeads, "comparing heads");
  run(store_sql::kMergeMapSources, "updating map sources");
  run(store_sql::kMergeHeads, "copying heads");
  run(store_sql::kDropWinningHeads, "comparing heads");
  MergeVersions(source_version);
  if (source_version >= 2) counts.failures = run(store_sql::kMergeFailures, "copying failures");
  run(store_sql::kDropOutdatedFailures, "dropping outdated failures");
  transaction.Commit();
  return counts;
}

void VacuumArtifactStore(const std::string& path) {
  OpenArtifactStore(path, StoreMode::kReadOnly);  // the usual checks; never creates a file
  const SqliteConnection connection(path, StoreMode::kReadWrite);
  sqlite3* db = connection.get();
  CheckSqlite(db, path, sqlite3_busy_timeout(db, kStoreBusyTimeoutMs), "setting the busy timeout");
  CheckSqlite(db, path, sqlite3_exec(db, "VACUUM", nullptr, nullptr, nullptr), "vacuuming");
  CheckSqlite(db, path,
              sqlite3_exec(db, "PRAGMA wal_checkpoint(TRUNCATE)", nullptr, nullptr, nullptr),
              "writing the log back after vacuuming");
}

}  // namespace areagraph
