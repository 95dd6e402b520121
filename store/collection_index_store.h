#pragma once

// The ArtifactStore over a collection index (collection_index.h), internal
// to store/: OpenArtifactStore gives it for an index file. Rows come from the
// index; a payload comes from the map's shard store, opened read-only on
// first use, and must still be there under the indexed key and digest.

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "common/error.h"
#include "store/artifact_store.h"
#include "store/collection_index.h"
#include "store/sqlite_connection.h"
#include "store/sqlite_statement.h"

namespace areagraph {

class CollectionIndexStore : public ArtifactStore {
 public:
  // Opens the index at `path` read-only; throws StoreError when it is not an
  // index this build reads.
  explicit CollectionIndexStore(const std::string& path);

  std::vector<MapRecord> ReadAllMaps() override;
  std::optional<MapRecord> ReadMap(const std::string& map_name) override;
  std::optional<ArtifactRecord> ReadArtifact(const std::string& map_name,
                                             const std::string& cache_key) override;
  std::optional<ArtifactRecord> ReadHead(const std::string& map_name,
                                         const std::string& stage) override;
  std::vector<ArtifactRecord> ReadArtifactSummaries(const std::string& map_name) override;
  std::optional<ArtifactRecord> ReadArtifactSummary(const std::string& map_name,
                                                    const std::string& cache_key) override;
  int64_t CountArtifacts(const std::string& map_name) override;
  bool HasArtifact(const std::string& map_name, const std::string& cache_key) override;
  std::optional<std::string> ReadHeadKey(const std::string& map_name,
                                         const std::string& stage) override;
  std::vector<VersionRecord> ReadVersions(const std::string& map_name) override;
  std::optional<VersionRecord> ReadVersion(const std::string& map_name,
                                           const std::string& cache_key) override;
  std::vector<FailureRecord> ReadFailures() override;
  // With ShardCheck::kFull; see VerifyCollectionIndex.
  std::vector<VerifyProblem> Verify(const std::vector<std::string>& file_input_stages,
                                    const std::function<void(int64_t, int64_t)>& progress,
                                    StructureCheck structure) override;
  std::vector<VerifyProblem> VerifyCollection(const std::vector<std::string>& file_input_stages,
                                              const std::function<void(int64_t, int64_t)>& progress,
                                              StructureCheck structure, ShardCheck shards);

  // An index is only read: these throw StoreError saying so.
  void WriteArtifact(const NewArtifact& artifact) override;
  void UpdateHead(const std::string& map_name, const std::string& cache_key) override;
  void RecordFailure(const FailureRecord& failure) override;
  void ClearFailure(const std::string& map_name) override;
  MaintenanceCounts CollectGarbage() override;
  MaintenanceCounts MergeFrom(const std::string& path) override;
  void BackupTo(const std::string& path) override;
  // Nothing to fold: an index is never written in WAL mode.
  bool FoldWriteAheadLog() override { return true; }
  void LeaveWriteAheadLogOnClose() override {}

  const CollectionIndexInfo& info() const { return info_; }

 private:
  // An indexed artifact row and the shard that holds its payload; a row
  // without details (payload digest and size, summary, compute time) takes
  // them from the shard.
  struct IndexedArtifact {
    ArtifactRecord record;
    int64_t shard_id = 0;
    bool detailed = false;
  };
  IndexedArtifact ReadIndexedRow(const SqliteStatement& statement, const std::string& map_name,
                                 int first) const;
  // The row that `statement` finds by map name and a second text (a key or a
  // stage), if any.
  std::optional<IndexedArtifact> ReadOneRow(LazyStatement& statement, const std::string& map_name,
                                            const std::string& second);
  // The shard of `shard_id` (a StoreError naming `map_name` when the index
  // lists no such shard).
  const CollectionShard* FindShard(int64_t shard_id, const std::string& map_name) const;
  // The shard of `shard_id`, opened read-only on first use; the error of a
  // missing or unreadable one names the shard and `map_name`.
  ArtifactStore& Shard(int64_t shard_id, const std::string& map_name);
  // The row with its payload from its shard.
  ArtifactRecord WithPayload(IndexedArtifact indexed);
  // The row with its details, from its shard when the index lacks them.
  ArtifactRecord WithDetails(IndexedArtifact indexed);
  // The error for an indexed artifact that its shard no longer holds as
  // indexed (`stored`: another payload under its key, else none).
  StoreError ShardChanged(const IndexedArtifact& indexed, bool stored) const;
  [[noreturn]] void ThrowReadOnly(const std::string& what) const;

  // Verify helpers (collection_index_verify.cc).
  void CheckShard(const CollectionShard& shard, const std::vector<std::string>& file_input_stages,
                  StructureCheck structure, ShardCheck check, int64_t total, int64_t& done,
                  const std::function<void(int64_t, int64_t)>& progress,
                  std::vector<VerifyProblem>& problems);
  void CheckIndexedRows(const CollectionShard& shard, ArtifactStore& store, ShardCheck check,
                        int64_t total, int64_t& done,
                        const std::function<void(int64_t, int64_t)>& progress,
                        std::vector<VerifyProblem>& problems);
  void CheckHeadsAndMaps(const CollectionShard& shard, ArtifactStore& store,
                         std::vector<VerifyProblem>& problems);
  std::vector<std::string> MapNamesOf(int64_t shard_id);

  const std::string path_;
  const SqliteConnection connection_;
  sqlite3* const db_;
  CollectionIndexInfo info_;
  std::map<int64_t, std::unique_ptr<ArtifactStore>> open_shards_;

  LazyStatement sql_read_all_maps_;
  LazyStatement sql_read_map_;
  LazyStatement sql_read_artifact_;
  LazyStatement sql_read_head_;
  LazyStatement sql_read_artifact_summaries_;
  LazyStatement sql_count_artifacts_;
  LazyStatement sql_has_artifact_;
  LazyStatement sql_read_head_key_;
  LazyStatement sql_read_versions_;
  LazyStatement sql_read_version_;
  LazyStatement sql_read_failures_;
};

// OpenArtifactStore for an index file: read-only, or a StoreError saying
// that an index is not written (run the tool on a shard store instead).
std::unique_ptr<ArtifactStore> OpenCollectionIndexStore(const std::string& path, StoreMode mode);

}  // namespace areagraph
