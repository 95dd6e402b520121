#pragma once

// A collection index: one small SQLite file that makes several shard stores
// (one per cluster task) read as one store, without copying their payloads.
// It holds each map's rows (map, artifacts without payloads, heads, history)
// and failures, and the shard file that holds the map's payloads, by a path
// relative to the index's folder (the folder moves as a whole).
// OpenArtifactStore opens an index read-only as a store whose payload reads
// go to the shards (collection_index_store.h); nothing writes through it.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "store/artifact_store.h"

namespace areagraph {

// The index's own schema version. Its file's user_version is this plus
// kCollectionIndexVersionBase: far above any store schema, so that a build
// that predates indexes refuses one as a store "newer than this build"
// instead of reading its payload-less rows.
constexpr int kCollectionIndexSchemaVersion = 1;
constexpr int kCollectionIndexVersionBase = 1000;

// Whether `path` is a collection index (and not a store, or nothing): its
// user_version says so. False for ":memory:", a missing file or one that
// SQLite cannot read (the ordinary open then says what is wrong).
bool IsCollectionIndex(const std::string& path);

// One shard store named by an index.
struct CollectionShard {
  int64_t id = 0;
  std::string path;           // as recorded: relative to the index's folder
  std::string resolved_path;  // where it is now, through the index's folder
  int64_t maps = 0;
  int64_t artifacts = 0;  // rows indexed
};

// What an index holds, without its rows.
struct CollectionIndexInfo {
  // Empty when every artifact of the shards is indexed; else the stages
  // whose heads alone are (ag-store index --only final).
  std::vector<std::string> head_stages;
  std::vector<CollectionShard> shards;
};

// Writes the index of `shards` (store files, each a shard of one collection:
// no map in two of them) into the new file `path`, removed again on failure.
// Shard paths are recorded relative to the folder of `final_path`, where the
// index will live (`path` may be a temporary name beside it). With
// `head_stages`, only the heads of those stages are indexed (their rows and
// the maps that have one); other artifacts stay in the shards, unread. The
// rows of `detail_stages` (small artifacts: the Area Graphs) hold their
// payload digest and size, summary and compute time; other rows leave them
// to the shard (collection_index_sql.h says why). Each shard is read
// without being changed, and only its rows' first columns are read, not the
// pages of big payloads. Throws StoreError naming the shard
// when it is not a store of schema 5 or newer (but not newer than this
// build's), is itself an index, is given twice, or shares a map with another.
std::vector<CollectionShard> WriteCollectionIndex(const std::string& path,
                                                  const std::string& final_path,
                                                  const std::vector<std::string>& shards,
                                                  const std::vector<std::string>& head_stages,
                                                  const std::vector<std::string>& detail_stages);

// The index's scope and shards. Throws StoreError when `path` is not a
// collection index this build reads.
CollectionIndexInfo ReadCollectionIndexInfo(const std::string& path);

// How far VerifyCollectionIndex reads the shards.
enum class ShardCheck {
  // Each shard's own Verify (SQLite's structure and every payload), then
  // whether it still holds what the index says.
  kFull,
  // Only whether each shard is there and holds what the index says: every
  // indexed artifact by key and payload digest, the same heads, no map the
  // index lacks. Reads no payload; for shards already verified where they
  // were written.
  kIndexedRowsOnly,
};

// ag-store verify of an index: SQLite's check of the index file (as
// `structure` says), then each shard as `shards` says. A missing shard or
// one that cannot be opened is one problem naming the shard and its maps; a
// shard's own problems and the ways it differs from the index (it changed
// since it was indexed) name the shard too. `progress` hears (done, total)
// over the indexed artifacts.
std::vector<VerifyProblem> VerifyCollectionIndex(
    const std::string& path, const std::vector<std::string>& file_input_stages,
    const std::function<void(int64_t, int64_t)>& progress, StructureCheck structure,
    ShardCheck shards);

// ag-store gc --keep final on one store: deletes every artifact that is not
// the head of one of `head_stages`, the other heads with them, and maps left
// without artifacts, in one transaction (history rows and failures stay).
// A later run of those maps recomputes the stages dropped. Throws StoreError
// for a collection index (trim its shards instead).
MaintenanceCounts KeepOnlyHeadsOf(const std::string& store_path,
                                  const std::vector<std::string>& head_stages);

}  // namespace areagraph
