#pragma once

#include <google/protobuf/message.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "store/artifact_store.h"

namespace areagraph {

// A stage's identity in cache keys. Bump `version` whenever the stage's
// output changes for the same input, so that cached results are recomputed.
struct StageInfo {
  const char* name;
  int version;
};

inline constexpr StageInfo kImportStage{"import", 1};
// clean 2: outlier threshold for k + 1 points; 3: unknown islands become free.
inline constexpr StageInfo kCleanStage{"clean", 3};
inline constexpr StageInfo kVoronoiStage{"voronoi", 2};  // 2: edges in face order
inline constexpr StageInfo kPruneStage{"prune", 1};
// cut 2: stores the W used (RoomWidthEstimate), and can estimate it (auto).
inline constexpr StageInfo kCutStage{"cut", 2};
// merge 2: growth stops at narrow gaps, freed cells stay out, small areas fold.
// merge 3: corridor pieces can be joined (merge.join_corridor_pieces).
// merge 4: open bays fold into their room (merge.fold_open_bays).
// merge 5: polygons are a simplified planar partition, passages lie on shared borders.
inline constexpr StageInfo kMergeStage{"merge", 5};

// The stages in pipeline order.
inline constexpr StageInfo kAllStages[] = {kImportStage, kCleanStage, kVoronoiStage,
                                           kPruneStage,  kCutStage,   kMergeStage};

// Whether two StageInfos name the same stage.
inline bool SameStage(const StageInfo& a, const StageInfo& b) {
  return std::string(a.name) == b.name;
}

// The stages whose artifacts `stage` reads, in the order their keys enter
// its cache key (import reads a file, so none). The one table that the stage
// executables, ag-pipeline, ag-run and ag-live share.
const std::vector<StageInfo>& InputStagesOf(const StageInfo& stage);

// What one stage run did.
struct StageRun {
  std::string cache_key;
  bool cache_hit = false;
  // Time spent computing, or 0 on a hit.
  double elapsed_ms = 0;
};

// Where a stage's inputs came from: the digests that enter its cache key.
struct StageInputs {
  std::vector<std::string> digests;
  // Set by ag-import only: recorded on the map row.
  std::optional<std::string> source_path;
  std::optional<std::string> source_digest;
};

// The cache key of a stage run: what RunCachedStage looks up and stores.
std::string StageCacheKey(const StageInfo& stage, const google::protobuf::Message& options,
                          const std::vector<std::string>& input_keys);

// Runs `compute` for (map, stage) unless the store already holds an artifact
// with the same cache key, in which case that artifact just becomes the head
// again. `force` recomputes regardless. The result is written in one
// transaction.
StageRun RunCachedStage(ArtifactStore& store, const std::string& map_name, const StageInfo& stage,
                        const google::protobuf::Message& options, const StageInputs& inputs,
                        const std::function<std::unique_ptr<google::protobuf::Message>()>& compute,
                        bool force = false);

// For the stage executables: the head keys of `stage`'s inputs. Throws
// InputError naming the executable to run first when one is missing.
StageInputs HeadInputs(ArtifactStore& store, const std::string& map_name, const StageInfo& stage);

// The artifact of `map_name` with `cache_key` parsed as T. Inputs are read by
// key, not as heads, so that the payload is the one whose key entered the
// cache key even when another process moves a head meanwhile.
template <typename T>
T ReadArtifactAs(ArtifactStore& store, const std::string& map_name, const std::string& cache_key);

// Non-template core of ReadArtifactAs.
void ParseArtifact(ArtifactStore& store, const std::string& map_name, const std::string& cache_key,
                   google::protobuf::Message* message);

// The head artifact of (map, stage) parsed as T, with its cache key. Throws
// InputError naming the executable to run first when it is missing.
template <typename T>
T ReadHeadArtifact(ArtifactStore& store, const std::string& map_name, const StageInfo& stage,
                   std::string* cache_key = nullptr);

// Non-template core of ReadHeadArtifact.
void ParseHeadArtifact(ArtifactStore& store, const std::string& map_name, const StageInfo& stage,
                       google::protobuf::Message* message, std::string* cache_key);

template <typename T>
T ReadArtifactAs(ArtifactStore& store, const std::string& map_name, const std::string& cache_key) {
  T message;
  ParseArtifact(store, map_name, cache_key, &message);
  return message;
}

template <typename T>
T ReadHeadArtifact(ArtifactStore& store, const std::string& map_name, const StageInfo& stage,
                   std::string* cache_key) {
  T message;
  ParseHeadArtifact(store, map_name, stage, &message, cache_key);
  return message;
}

}  // namespace areagraph
