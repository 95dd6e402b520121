#include "stages/common/stage.h"

#include <chrono>

#include "stages/common/pipeline_options.h"
#include "store/cache_key.h"
#include "store/error.h"

namespace areagraph {

std::string StageCacheKey(const StageInfo& stage, const google::protobuf::Message& options,
                          const std::vector<std::string>& input_keys) {
  return ComputeCacheKey(stage.name, stage.version, CanonicalBytes(options), input_keys);
}

StageRun RunCachedStage(ArtifactStore& store, const std::string& map_name, const StageInfo& stage,
                        const google::protobuf::Message& options, const StageInputs& inputs,
                        const std::function<std::unique_ptr<google::protobuf::Message>()>& compute,
                        bool force) {
  StageRun run;
  run.cache_key = StageCacheKey(stage, options, inputs.digests);
  if (!force) {
    // Key lookups only: a hit costs no payload read. A damaged payload shows
    // when a later stage reads it (or with ag-store verify).
    if (store.ReadHeadKey(map_name, stage.name) == run.cache_key) {
      run.cache_hit = true;
      return run;
    }
    if (store.HasArtifact(map_name, run.cache_key)) {
      store.UpdateHead(map_name, run.cache_key);
      run.cache_hit = true;
      return run;
    }
  }

  const auto start = std::chrono::steady_clock::now();
  std::unique_ptr<google::protobuf::Message> result = compute();
  run.elapsed_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

  NewArtifact artifact;
  artifact.map_name = map_name;
  artifact.stage = stage.name;
  artifact.cache_key = run.cache_key;
  artifact.input_keys = inputs.digests;
  artifact.options_text = CanonicalText(options);
  artifact.stage_version = stage.version;
  artifact.proto_type = result->GetTypeName();
  if (!result->SerializeToString(&artifact.payload)) {
    throw Error(std::string("stage '") + stage.name + "' produced an artifact too big to store");
  }
  artifact.elapsed_ms = run.elapsed_ms;
  artifact.source_path = inputs.source_path;
  artifact.source_digest = inputs.source_digest;
  store.WriteArtifact(artifact);
  return run;
}

namespace {

InputError MissingInput(ArtifactStore& store, const std::string& map_name, const StageInfo& stage) {
  if (!store.ReadMap(map_name)) {
    return InputError("map '" + map_name + "' is not in the store; run ag-import first");
  }
  return InputError("map '" + map_name + "' has no " + stage.name + " artifact; run ag-" +
                    stage.name + " first");
}

}  // namespace

const std::vector<StageInfo>& InputStagesOf(const StageInfo& stage) {
  static const std::vector<StageInfo> kNone;
  static const std::vector<StageInfo> kClean = {kImportStage};
  static const std::vector<StageInfo> kVoronoi = {kCleanStage};
  static const std::vector<StageInfo> kPrune = {kVoronoiStage, kCleanStage};
  static const std::vector<StageInfo> kCut = {kPruneStage, kCleanStage};
  static const std::vector<StageInfo> kMerge = {kCutStage, kCleanStage};
  if (SameStage(stage, kCleanStage)) return kClean;
  if (SameStage(stage, kVoronoiStage)) return kVoronoi;
  if (SameStage(stage, kPruneStage)) return kPrune;
  if (SameStage(stage, kCutStage)) return kCut;
  if (SameStage(stage, kMergeStage)) return kMerge;
  return kNone;
}

StageInputs HeadInputs(ArtifactStore& store, const std::string& map_name, const StageInfo& stage) {
  StageInputs inputs;
  for (const StageInfo& input : InputStagesOf(stage)) {
    std::optional<std::string> key = store.ReadHeadKey(map_name, input.name);
    if (!key) throw MissingInput(store, map_name, input);
    inputs.digests.push_back(*key);
  }
  return inputs;
}

void ParseArtifact(ArtifactStore& store, const std::string& map_name, const std::string& cache_key,
                   google::protobuf::Message* message) {
  const std::optional<ArtifactRecord> record = store.ReadArtifact(map_name, cache_key);
  if (!record || record->proto_type != message->GetTypeName() ||
      !message->ParseFromString(record->payload)) {
    throw StoreError("artifact " + cache_key.substr(0, 12) + " of map '" + map_name +
                     "' is missing or not a valid " + message->GetTypeName());
  }
}

void ParseHeadArtifact(ArtifactStore& store, const std::string& map_name, const StageInfo& stage,
                       google::protobuf::Message* message, std::string* cache_key) {
  const std::optional<ArtifactRecord> head = store.ReadHead(map_name, stage.name);
  if (!head) throw MissingInput(store, map_name, stage);
  if (head->proto_type != message->GetTypeName() || !message->ParseFromString(head->payload)) {
    throw StoreError("the " + std::string(stage.name) + " artifact of map '" + map_name +
                     "' is not a valid " + message->GetTypeName());
  }
  if (cache_key != nullptr) *cache_key = head->cache_key;
}

}  // namespace areagraph
