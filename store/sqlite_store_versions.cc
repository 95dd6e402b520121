// Each map's history of versions in the SQLite store (schema 4): written with
// the artifact it records, read by ag-inspect --history and by the stages
// that read their previous version, copied by ag-store merge.

#include <sqlite3.h>

#include "common/error.h"
#include "store/sqlite_artifact_store.h"
#include "store/sqlite_versions_sql.h"

namespace areagraph {

void SqliteArtifactStore::PrepareVersionStatements() {
  if (!HasVersionsTable()) return;
  sql_stmt_insert_version_ = Prepare(store_sql::kInsertVersion, "recording a version");
  sql_stmt_read_versions_ = Prepare(store_sql::kReadVersions, "reading the history of a map");
  sql_stmt_read_version_ = Prepare(store_sql::kReadVersion, "reading a version");
}

void SqliteArtifactStore::InsertVersion(int64_t map_id, const NewArtifact& artifact) {
  if (!HasVersionsTable()) {
    throw StoreError("store '" + path_ + "' has schema version " + std::to_string(schema_version_) +
                     " without a history of versions; open it for writing to upgrade it");
  }
  if (artifact.version->number < 1) {
    throw StoreError("version number " + std::to_string(artifact.version->number) + " of a " +
                     artifact.stage + " artifact is not positive");
  }
  SqliteStatement& insert = *sql_stmt_insert_version_;
  StatementUse use(insert);
  insert.BindInt64(1, map_id);
  insert.BindText(2, artifact.cache_key);
  insert.BindText(3, artifact.stage);
  insert.BindText(4, artifact.version->predecessor_key);
  insert.BindInt64(5, artifact.version->number);
  insert.Step();
}

VersionRecord store_internal::ReadVersionRow(const SqliteStatement& statement) {
  VersionRecord version;
  version.cache_key = statement.ColumnText(0, "versions.cache_key");
  version.predecessor_key = statement.ColumnText(1, "versions.predecessor_key");
  version.number = statement.ColumnInt64(2, "versions.number");
  version.stage = statement.ColumnText(3, "versions.stage");
  version.created_at = statement.ColumnText(4, "versions.created_at");
  version.stored = statement.ColumnInt64(5, "artifacts.id") != 0;
  version.is_head = statement.ColumnInt64(6, "heads.artifact_id") != 0;
  return version;
}

std::vector<VersionRecord> SqliteArtifactStore::ReadVersions(const std::string& map_name) {
  std::vector<VersionRecord> versions;
  if (!HasVersionsTable()) return versions;
  SqliteStatement& statement = *sql_stmt_read_versions_;
  StatementUse use(statement);
  statement.BindText(1, map_name);
  while (statement.Step()) versions.push_back(store_internal::ReadVersionRow(statement));
  return versions;
}

std::optional<VersionRecord> SqliteArtifactStore::ReadVersion(const std::string& map_name,
                                                              const std::string& cache_key) {
  if (!HasVersionsTable()) return std::nullopt;
  SqliteStatement& statement = *sql_stmt_read_version_;
  StatementUse use(statement);
  statement.BindText(1, map_name);
  statement.BindText(2, cache_key);
  if (!statement.Step()) return std::nullopt;
  return store_internal::ReadVersionRow(statement);
}

void SqliteArtifactStore::MergeVersions(int source_version) {
  if (source_version < 4) return;  // the source has no history
  SqliteStatement statement(db_, path_, store_sql::kMergeVersions, "merging: copying versions");
  StatementUse use(statement);
  while (statement.Step()) {
  }
}

}  // namespace areagraph
