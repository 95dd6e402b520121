#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

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
  double elapsed_ms = 0;
  // Only ag-import sets these; they update the map row.
  std::optional<std::string> source_path;
  std::optional<std::string> source_digest;
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

  // Inserts the artifact (creating the map row if needed) and makes it the
  // head of its (map, stage), all in one transaction. Writing a key that the
  // map already has replaces that row.
  virtual void WriteArtifact(const NewArtifact& artifact) = 0;
  // Makes an existing artifact the head of its (map, stage); for cache hits.
  virtual void UpdateHead(const std::string& map_name, const std::string& cache_key) = 0;
};

enum class StoreMode { kReadWrite, kReadOnly };

// Opens or creates a store. ":memory:" gives a private in-memory store.
// Throws StoreError when the file is not SQLite, is from a newer schema, is
// locked beyond the busy timeout, or cannot be created.
std::unique_ptr<ArtifactStore> OpenArtifactStore(const std::string& path,
                                                 StoreMode mode = StoreMode::kReadWrite);

// The schema version this build writes and the newest it reads.
constexpr int kStoreSchemaVersion = 1;

}  // namespace areagraph
