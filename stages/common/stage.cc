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

void ParseHeadArtifact(ArtifactStore& store, const std::string& map_name, const StageInfo& stage,
                       google::protobuf::Message* message, std::string* cache_key) {
  const std::optional<ArtifactRecord> head = store.ReadHead(map_name, stage.name);
  if (!head) {
    if (!store.ReadMap(map_name)) {
      throw InputError("map '" + map_name + "' is not in the store; run ag-import first");
    }
    throw InputError("map '" + map_name + "' has no " + stage.name + " artifact; run ag-" +
                     stage.name + " first");
  }
  if (head->proto_type != message->GetTypeName() || !message->ParseFromString(head->payload)) {
    throw StoreError("the " + std::string(stage.name) + " artifact of map '" + map_name +
                     "' is not a valid " + message->GetTypeName());
  }
  if (cache_key != nullptr) *cache_key = head->cache_key;
}

}  // namespace areagraph
