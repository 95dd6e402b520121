#pragma once

// The SQLite implementation of ArtifactStore, internal to store/: others get
// it through OpenArtifactStore. Split over sqlite_artifact_store.cc (opening,
// reads, writes, failures), sqlite_store_versions.cc (each map's history) and
// sqlite_store_maintenance.cc (verify, gc, merge).

#include <sqlite3.h>

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "store/artifact_store.h"
#include "store/sqlite_connection.h"
#include "store/sqlite_statement.h"
#include "store/sqlite_transaction.h"

namespace areagraph {

class SqliteArtifactStore : public ArtifactStore {
 public:
  SqliteArtifactStore(const std::string& path, StoreMode mode);
  // Builds a new store's file at `path`, a fresh empty file no one else
  // knows of: schema and WAL mode written without journal or syncs
  // (sqlite_store_creation.cc makes it whole, then gives it its name).
  static void BuildUnpublishedFile(const std::string& path);
  // A read-write store folds its write-ahead log into the file on close,
  // unless LeaveWriteAheadLogOnClose said otherwise.
  ~SqliteArtifactStore() override;

  std::vector<MapRecord> ReadAllMaps() override;
  std::optional<MapRecord> ReadMap(const std::string& map_name) override;
  std::optional<ArtifactRecord> ReadArtifact(const std::string& map_name,
                                             const std::string& cache_key) override;
  std::optional<ArtifactRecord> ReadHead(const std::string& map_name,
                                         const std::string& stage) override;
  std::vector<ArtifactRecord> ReadArtifactSummaries(const std::string& map_name) override;
  std::optional<ArtifactRecord> ReadArtifactSummary(const std::string& map_name,
                                                    const std::string& cache_key) override;
  void WriteArtifact(const NewArtifact& artifact) override;
  void UpdateHead(const std::string& map_name, const std::string& cache_key) override;

  bool HasArtifact(const std::string& map_name, const std::string& cache_key) override;
  std::optional<std::string> ReadHeadKey(const std::string& map_name,
                                         const std::string& stage) override;

  std::vector<VersionRecord> ReadVersions(const std::string& map_name) override;
  std::optional<VersionRecord> ReadVersion(const std::string& map_name,
                                           const std::string& cache_key) override;

  void RecordFailure(const FailureRecord& failure) override;
  void ClearFailure(const std::string& map_name) override;
  std::vector<FailureRecord> ReadFailures() override;

  std::vector<VerifyProblem> Verify(const std::vector<std::string>& file_input_stages,
                                    const std::function<void(int64_t, int64_t)>& progress,
                                    StructureCheck structure) override;
  MaintenanceCounts CollectGarbage() override;
  MaintenanceCounts MergeFrom(const std::string& path) override;
  bool FoldWriteAheadLog() override;
  void LeaveWriteAheadLogOnClose() override;
  void BackupTo(const std::string& path) override;

 private:
  struct UnpublishedFile {};
  SqliteArtifactStore(const std::string& path, UnpublishedFile);

  // Open-time steps, in the order that keeps a bad file untouched.
  struct SchemaState {
    int user_version = 0;
    int64_t schema_objects = 0;  // tables and indexes of any kind
  };
  SchemaState ReadSchemaState();
  void CheckIsAreagraphStore(const SchemaState& state, StoreMode mode);
  void Exec(const char* sql, const std::string& action);
  void EnableWriteAheadLog();
  // Runs a journal_mode pragma and returns the mode it reports; SQLite's
  // result code goes to `rc` when given, else a failure throws.
  std::string JournalMode(const char* pragma, int* rc = nullptr);
  // Creates the schema, or upgrades an older one, in one transaction.
  void CreateOrUpgradeSchema();
  void CreateMapsTable();
  void CreateArtifactsTable();
  void CreateHeadsTable();
  void PrepareStatements();
  // The failures statements need schema 2; a read-only version-1 store has none.
  bool HasFailuresTable() const { return schema_version_ >= 2; }
  bool HasSummaryLines() const { return schema_version_ >= 3; }
  // The versions statements need schema 4; older read-only stores have none.
  bool HasVersionsTable() const { return schema_version_ >= 4; }
  // Schema 5 keeps a codec per payload; older read-only stores are raw.
  bool HasPayloadCodecs() const { return schema_version_ >= 5; }
  // Schema 6 keeps a digest of each artifact row's columns.
  bool HasRowDigests() const { return schema_version_ >= 6; }

  // The statement, prepared on its first use (LazyStatement).
  LazyStatement Prepare(const char* sql, const std::string& action);
  SqliteTransaction BeginTransaction();
  MapRecord ReadMapRow(const SqliteStatement& statement) const;
  // Reads the row of a kRead{Artifact,Head,ArtifactSummaries} statement; the
  // last column is the payload, or its size in a summary.
  ArtifactRecord ReadArtifactRow(const SqliteStatement& statement, const std::string& map_name,
                                 bool with_payload) const;
  void WriteHead(int64_t map_id, const std::string& stage, int64_t artifact_id);

  // History helpers (sqlite_store_versions.cc).
  void PrepareVersionStatements();
  // Records `artifact` (which has a version) in its map's history; inside
  // WriteArtifact's transaction.
  void InsertVersion(int64_t map_id, const NewArtifact& artifact);
  // Copies the history rows of the attached merge source (schema 4 and later).
  void MergeVersions(int source_version);

  // Maintenance helpers (sqlite_store_maintenance.cc).
  void CheckArtifacts(const std::vector<std::string>& file_input_stages,
                      const std::function<void(int64_t, int64_t)>& progress,
                      std::vector<VerifyProblem>& problems);
  void CheckArtifactRow(SqliteStatement& row, const std::vector<std::string>& file_input_stages,
                        std::vector<VerifyProblem>& problems);
  void FindBrokenHeads(std::vector<VerifyProblem>& problems);
  void CheckCanMergeFrom(const std::string& path);
  MaintenanceCounts CopyFromMergeSource(const std::string& path, int source_version);

  // Integrity helpers (sqlite_store_integrity.cc).
  // SQLite's findings on `schema` ("main" or "merge_source"); empty when sound.
  std::vector<std::string> CheckStructure(const char* schema, StructureCheck structure);
  // Throws StoreError naming `path` when an artifact that the merge would
  // copy from it has a payload that fails its digest or is not protobuf.
  void CheckMergeSourcePayloads(const std::string& path, int source_version);
  // The same for an artifact row whose columns fail their row digest.
  void CheckMergeSourceRows(const std::string& path, int source_version);

  const std::string path_;
  const StoreMode mode_;
  const SqliteConnection connection_;  // closes after the statements below
  sqlite3* const db_;
  int schema_version_ = 0;     // of the open file, after any upgrade
  bool fold_on_close_ = true;  // false once LeaveWriteAheadLogOnClose ran

  LazyStatement sql_stmt_begin_;
  LazyStatement sql_stmt_commit_;
  LazyStatement sql_stmt_rollback_;
  LazyStatement sql_stmt_read_all_maps_;
  LazyStatement sql_stmt_read_map_;
  LazyStatement sql_stmt_read_artifact_;
  LazyStatement sql_stmt_read_head_;
  LazyStatement sql_stmt_read_artifact_summaries_;
  LazyStatement sql_stmt_read_artifact_summary_;
  // Null for a store older than schema 3, which is opened read-only.
  LazyStatement sql_stmt_read_artifact_ref_;
  LazyStatement sql_stmt_read_artifact_id_;
  LazyStatement sql_stmt_upsert_map_;
  LazyStatement sql_stmt_upsert_artifact_;
  LazyStatement sql_stmt_write_head_;
  LazyStatement sql_stmt_has_artifact_;
  LazyStatement sql_stmt_read_head_key_;
  // Null when !HasFailuresTable().
  LazyStatement sql_stmt_record_failure_;
  LazyStatement sql_stmt_clear_failure_;
  LazyStatement sql_stmt_read_failures_;
  // Null when !HasVersionsTable().
  LazyStatement sql_stmt_insert_version_;
  LazyStatement sql_stmt_read_versions_;
  LazyStatement sql_stmt_read_version_;
};

namespace store_internal {

// The form of a statement for a store of schema `version`: older stores have
// no row digest (before 6), no payload codec (before 5) and no summary lines
// (before 3).
inline const char* ForSchema(int version, const char* current, const char* before6,
                             const char* before5, const char* before3) {
  return version >= 6 ? current : version >= 5 ? before6 : version >= 3 ? before5 : before3;
}

// Makes a new store file at `path` when none is there (sqlite_store_creation.cc).
void CreateMissingStoreFile(const std::string& path);

// Input keys are stored newline-joined.
std::vector<std::string> SplitLines(const std::string& joined);

// A row of store_sql::kReadVersions / kReadVersion, and of kReadFailures
// (also a collection index's, whose tables answer the same statements).
VersionRecord ReadVersionRow(const SqliteStatement& statement);
FailureRecord ReadFailureRow(const SqliteStatement& statement);

// What a row whose columns do not match its row digest (schema 6) is.
inline constexpr char kRowDigestMismatch[] =
    "row digest mismatch: its key, inputs, options, summary or time were changed";

// Registers the SQL function ag_row_digest(map_name, stage, cache_key,
// input_keys, options, stage_version, proto_type, payload_digest, summary,
// created_at), ArtifactRowDigest in SQL, on the connection.
void RegisterRowDigestFunction(sqlite3* db, const std::string& path);

// What is wrong with a stored payload (decoded with `codec`): a damaged
// frame, "payload digest mismatch" or "payload is not protobuf wire format";
// nullopt when it is intact.
std::optional<std::string> PayloadProblem(std::string_view stored, int64_t codec,
                                          std::string_view digest);

}  // namespace store_internal

}  // namespace areagraph
