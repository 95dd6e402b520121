#pragma once

#include <google/protobuf/message.h>

#include <functional>
#include <memory>
#include <string>

#include "proto/pipeline_options.pb.h"
#include "stages/common/stage_info.h"
#include "stages/pipeline/artifact_memo.h"
#include "stages/pipeline/stage_table.h"
#include "store/artifact_store.h"

namespace areagraph {

// Runs `compute` for (map, stage) unless the store already holds an artifact
// with the same cache key, in which case that artifact just becomes the head
// again. `force` recomputes regardless. The result is written, with its
// summary line, in one transaction. Whatever `compute` or the write throws is
// rethrown as a MapStepError naming the map and the stage. A computed
// artifact is also kept in `memo` when there is one.
StageRun RunCachedStage(ArtifactStore& store, const std::string& map_name,
                        const StageDefinition& stage, const proto::PipelineOptions& options,
                        const StageInputs& inputs, const std::function<MessagePtr()>& compute,
                        bool force = false, ArtifactMemo* memo = nullptr);

// Runs a stage that reads artifacts (not import) through the cache on the
// current heads of its inputs: HeadInputs, then RunCachedStage with the
// table's compute function on the inputs read by key, or taken from `memo`
// when they were computed in this process (and kept there). The compute gets
// `between_steps` as its InputRelease's hook.
StageRun RunStageOnHeads(ArtifactStore& store, const std::string& map_name,
                         const StageDefinition& stage, const proto::PipelineOptions& options,
                         bool force = false, ArtifactMemo* memo = nullptr,
                         const std::function<void()>& between_steps = nullptr);

// The head keys of `stage`'s inputs. Throws MapStepError naming the
// executable to run first when one is missing.
StageInputs HeadInputs(ArtifactStore& store, const std::string& map_name,
                       const StageDefinition& stage);

// The artifact of `map_name` with `cache_key` parsed as T. Inputs are read by
// key, not as heads, so that the payload is the one whose key entered the
// cache key even when another process moves a head meanwhile.
template <typename T>
T ReadArtifactAs(ArtifactStore& store, const std::string& map_name, const std::string& cache_key);

// Non-template core of ReadArtifactAs. Throws StoreError when the artifact is
// missing, of another type, does not parse, or was written in a newer format
// than this build knows (StageDefinition::format_version).
void ParseArtifact(ArtifactStore& store, const std::string& map_name, const std::string& cache_key,
                   google::protobuf::Message* message);

// The head artifact of (map, stage) parsed as T, with its cache key. Throws
// InputError naming the executable to run first when it is missing, and as
// ParseArtifact does.
template <typename T>
T ReadHeadArtifact(ArtifactStore& store, const std::string& map_name, const StageInfo& stage,
                   std::string* cache_key = nullptr);

// Non-template core of ReadHeadArtifact.
void ParseHeadArtifact(ArtifactStore& store, const std::string& map_name, const StageInfo& stage,
                       google::protobuf::Message* message, std::string* cache_key);

// Checks a parsed artifact's format_version against what this build writes
// for its type; throws StoreError naming `what` when it is newer.
void CheckFormatVersion(const google::protobuf::Message& artifact, const std::string& what);

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
