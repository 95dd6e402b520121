#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "store/payload_encoder.h"

namespace areagraph {

// A map known to the store: a name, and the file its head import came from.
struct MapRecord {
  int64_t id = 0;
  std::string name;
  std::string source_path;
  std::string source_digest;
};

// Everything the store keeps about one artifact. `payload` is empty in
// summaries (ReadArtifactSummaries), which carry `payload_bytes` instead.
struct ArtifactRecord {
  std::string map_name;
  std::string stage;
  std::string cache_key;
  std::vector<std::string> input_keys;
  std::string options_text;
  int stage_version = 0;
  std::string proto_type;
  std::string payload;
  int64_t payload_bytes = 0;
  std::string payload_digest;
  std::string created_at;  // UTC, ISO 8601
  double elapsed_ms = 0;
  // One line about the artifact's content, written by its stage; empty for
  // artifacts stored before schema 3.
  std::string summary_line;
  bool is_head = false;
};

// An artifact's place in its map's history of versions: what a stage that
// reads its previous version (match) records beside the artifact.
struct VersionLink {
  // Cache key of the previous version; empty for the first.
  std::string predecessor_key;
  // 1 for the first version, then one more than the predecessor's.
  int64_t number = 1;
};

// One version in a map's history (the versions table).
struct VersionRecord {
  std::string cache_key;
  std::string predecessor_key;
  int64_t number = 0;
  std::string stage;
  std::string created_at;  // UTC, ISO 8601: when the version was made
  // Whether the artifact is still stored (gc drops superseded versions that
  // no head reaches; their rows stay) and whether it is its stage's head.
  bool stored = false;
  bool is_head = false;
};

// What a stage hands the store to persist. The store fills in the digest, the
// creation time and the head flag.
struct NewArtifact {
  std::string map_name;
  std::string stage;
  std::string cache_key;
  std::vector<std::string> input_keys;
  std::string options_text;
  int stage_version = 0;
  std::string proto_type;
  std::string payload;
  // When set, the payload already compressed and hashed (EncodeMessagePayload,
  // without its raw bytes in memory); `payload` is then ignored.
  std::optional<EncodedPayload> encoded_payload;
  double elapsed_ms = 0;
  std::string summary_line;
  // Only ag-import sets these; they update the map row.
  std::optional<std::string> source_path;
  std::optional<std::string> source_digest;
  // Only stages that read their previous version set this: the artifact is
  // then also recorded in the map's history, in the same transaction.
  std::optional<VersionLink> version;
};

// A map that failed in a runner, with the stage it failed in. Keyed by map
// name, not by the maps table: a map whose import failed has no map row.
struct FailureRecord {
  std::string map_name;
  std::string stage;
  std::string message;
  std::string source_path;
  std::string failed_at;  // UTC, ISO 8601; filled in by the store
};

// What `ag-store verify` found wrong with one artifact.
struct VerifyProblem {
  std::string map_name;
  std::string stage;
  std::string cache_key;
  std::string problem;
};

// What CollectGarbage or MergeFrom changed.
struct MaintenanceCounts {
  int64_t maps = 0;
  int64_t artifacts = 0;
  int64_t payload_bytes = 0;
  int64_t failures = 0;
};

// How far Verify checks SQLite's own structures (pages, b-trees, indexes)
// besides the payloads: damage there makes every tool fail with "database
// disk image is malformed" while the payloads may still read fine.
enum class StructureCheck {
  // PRAGMA integrity_check: also that every index matches its table.
  kFull,
  // PRAGMA quick_check: the same without index contents; faster on big stores.
  kQuick,
};

// The artifact store. One SQLite file (or ":memory:") holds maps, artifacts
// and the head of each (map, stage). Every Write*/Update* is one transaction.
// Errors are thrown as StoreError with a message fit for the user.
class ArtifactStore {
 public:
  virtual ~ArtifactStore() = default;

  virtual std::vector<MapRecord> ReadAllMaps() = 0;
  virtual std::optional<MapRecord> ReadMap(const std::string& map_name) = 0;

  // The artifact of `map_name` with this cache key, payload included and its
  // digest verified; nullopt when absent.
  virtual std::optional<ArtifactRecord> ReadArtifact(const std::string& map_name,
                                                     const std::string& cache_key) = 0;
  // The head artifact of (map, stage), payload verified; nullopt when absent.
  virtual std::optional<ArtifactRecord> ReadHead(const std::string& map_name,
                                                 const std::string& stage) = 0;
  // All artifacts of a map without payloads, oldest first.
  virtual std::vector<ArtifactRecord> ReadArtifactSummaries(const std::string& map_name) = 0;
  // One artifact without its payload; nullopt when absent.
  virtual std::optional<ArtifactRecord> ReadArtifactSummary(const std::string& map_name,
                                                            const std::string& cache_key) = 0;
  // How many artifacts the map has (a collection index counts without asking
  // its shards for the summaries).
  virtual int64_t CountArtifacts(const std::string& map_name) {
    return static_cast<int64_t>(ReadArtifactSummaries(map_name).size());
  }

  // Inserts the artifact (creating the map row if needed) and makes it the
  // head of its (map, stage), all in one transaction. Writing a key that the
  // map already has replaces that row.
  virtual void WriteArtifact(const NewArtifact& artifact) = 0;
  // WriteArtifact with `message` serialized as the payload (`artifact`'s
  // payload and encoded_payload are ignored). No reference to `message` is
  // kept once this returns. Here the write is done when it returns; a
  // write-behind store (write_behind_store.h) may finish it later.
  virtual void WriteMessageArtifact(NewArtifact artifact,
                                    const google::protobuf::MessageLite& message) {
    artifact.encoded_payload = EncodeMessagePayload(message);
    WriteArtifact(artifact);
  }
  // WriteMessageArtifact for a message that no one changes while `message`
  // holds it (a stage's result, shared with the next stages): a write-behind
  // store may serialize even a big one later, on its own thread.
  virtual void WriteSharedMessageArtifact(
      NewArtifact artifact, std::shared_ptr<const google::protobuf::MessageLite> message) {
    WriteMessageArtifact(std::move(artifact), *message);
  }
  // Returns once every artifact handed to this store is in it; throws the
  // error of one that failed. Nothing to do where every write is done at once.
  virtual void FinishWrites() {}
  // Makes an existing artifact the head of its (map, stage); for cache hits.
  virtual void UpdateHead(const std::string& map_name, const std::string& cache_key) = 0;

  // Cheap cache checks for runners: no payload is read.
  virtual bool HasArtifact(const std::string& map_name, const std::string& cache_key) = 0;
  virtual std::optional<std::string> ReadHeadKey(const std::string& map_name,
                                                 const std::string& stage) = 0;

  // A map's history of versions (see NewArtifact::version), oldest first,
  // and one version by key; empty / nullopt for a store older than schema 4.
  virtual std::vector<VersionRecord> ReadVersions(const std::string& map_name) = 0;
  virtual std::optional<VersionRecord> ReadVersion(const std::string& map_name,
                                                   const std::string& cache_key) = 0;

  // Failures recorded by runners; at most one per map, the latest.
  virtual void RecordFailure(const FailureRecord& failure) = 0;
  virtual void ClearFailure(const std::string& map_name) = 0;
  virtual std::vector<FailureRecord> ReadFailures() = 0;

  // Maintenance (ag-store). Verify first runs SQLite's own check
  // (`structure`; each finding is a problem without map or stage), then
  // reads every payload, one at a time, and checks its digest and that it is
  // well-formed protobuf wire format (the store does not know the message
  // types); it also checks that every head points at an artifact of its own
  // map and stage, and that every input key names an artifact of the same
  // map, except for artifacts of `file_input_stages`, whose input is the
  // digest of a file. A store too damaged to be read to the end gives a
  // problem saying so, not an exception. `progress` hears (done, total) after
  // each artifact.
  virtual std::vector<VerifyProblem> Verify(
      const std::vector<std::string>& file_input_stages,
      const std::function<void(int64_t, int64_t)>& progress = nullptr,
      StructureCheck structure = StructureCheck::kFull) = 0;
  // Deletes artifacts that no head reaches, directly or through input keys
  // (followed within the map), and then maps left without any artifact, in
  // one transaction. The rows of a map's history stay (ReadVersions then
  // says which versions are no longer stored). Counts what was deleted; the file shrinks only after
  // VacuumArtifactStore (store/store_maintenance.h).
  virtual MaintenanceCounts CollectGarbage() = 0;
  // Copies the maps, artifacts, heads and failures of the store at `path`
  // into this one, in one transaction, and counts what was new. Maps match by
  // name and artifacts by (map, cache key); an artifact both stores hold is
  // kept as it is here. A (map, stage) head both hold goes to the artifact
  // created later (a tie keeps this store's), and the map's source follows
  // its import head. A failure goes to the later one, and is dropped when the
  // merged map has a head created after it. The history rows of both are
  // kept (matched by map and key). The store at `path` must pass SQLite's
  // integrity_check (indexes included: lookups by name and key go through
  // them), every artifact row of it its row digest, and every payload copied
  // is checked (digest and wire format) before the transaction commits.
  // Throws StoreError naming `path` when it is damaged (and nothing of it is
  // merged), when it is this store, or when it is not an areagraph store of
  // this build's schema or older.
  virtual MaintenanceCounts MergeFrom(const std::string& path) = 0;

  // Writes everything in the write-ahead log back into the store file and
  // empties the log (a TRUNCATE checkpoint), so that the file alone holds
  // every artifact. Does not wait for others: returns false when another
  // process is reading or writing (its own close folds the log then); throws
  // StoreError (UnfoldedLogMessage) when the fold fails, e.g. on a full disk.
  // Every read-write store does this when it closes.
  virtual bool FoldWriteAheadLog() = 0;
  // For a process that hands the store to writers coming next (ag-run before
  // its workers): closing then leaves the write-ahead log for them to append
  // to instead of folding it, which saves two file syncs there and a new log
  // (two more) for the next writer. The log stays safe to replay; whoever
  // closes last with folding on makes the file whole again.
  virtual void LeaveWriteAheadLogOnClose() = 0;

  // Copies the whole store, consistent at one moment even while others
  // write, into a new SQLite file at `path` through SQLite's online backup,
  // with the log folded in. Throws StoreError when `path` cannot be written.
  virtual void BackupTo(const std::string& path) = 0;
};

enum class StoreMode { kReadWrite, kReadOnly };

// Opens or creates a store. ":memory:" gives a private in-memory store.
// Throws StoreError when the file is not SQLite, is from a newer schema, is
// locked beyond the busy timeout, or cannot be created.
std::unique_ptr<ArtifactStore> OpenArtifactStore(const std::string& path,
                                                 StoreMode mode = StoreMode::kReadWrite);

// Whether the store file at `path` has a write-ahead log beside it that may
// hold commits not yet folded into the file: a fold empties the log and the
// last close removes it. Looks at the file only, without opening the store
// (which would replay the whole log first); false for ":memory:".
bool HasWriteAheadLog(const std::string& path);

// What to tell the user when the write-ahead log of store `path` could not
// be folded into its file (`why`: a full disk): the -wal then holds commits
// that the file alone lacks.
std::string UnfoldedLogMessage(const std::string& path, const std::string& why);

// The message of the last store closed since the previous call whose log
// could not be folded on close (UnfoldedLogMessage), or nullopt. A store's
// close cannot throw; RunCommand reports this instead.
std::optional<std::string> TakeUnfoldedLogProblem();

// The schema version this build writes and the newest it reads. 2 added the
// failures table, 3 the artifacts' summary line, 4 the versions table (each
// map's history of Area Graphs), 5 zstd-compressed payloads (a codec per
// artifact; rows written before stay uncompressed and readable), 6 a digest
// of each artifact row's other columns (key, inputs, options, summary, ...;
// store/row_digest.h), checked wherever the row is read, by verify and by
// merge. An older store is upgraded when opened read-write (rows written
// before get their digest then), and read as it is (without failures,
// summary lines, history or row checks) when opened read-only.
constexpr int kStoreSchemaVersion = 6;

}  // namespace areagraph
