#include "stages/pipeline/stage_versions.h"

#include <algorithm>

#include "common/error.h"
#include "common/text.h"

namespace areagraph {

VersionLink PreviousVersionOf(ArtifactStore& store, const std::string& map_name,
                              const StageDefinition& stage, const proto::PipelineOptions& options,
                              const std::vector<std::string>& input_keys) {
  const std::optional<std::string> head = store.ReadHeadKey(map_name, stage.info.name);
  if (!head) return VersionLink{};
  // A head outside the history (none is written that way) starts a new one.
  const std::optional<VersionRecord> record = store.ReadVersion(map_name, *head);
  if (!record) return VersionLink{*head, 2};
  const VersionLink head_link{record->predecessor_key, record->number};
  if (StageCacheKey(stage.info, stage.options_of(options), CacheKeyInputs(input_keys, head_link)) ==
      *head) {
    return head_link;
  }
  return VersionLink{*head, record->number + 1};
}

std::vector<std::string> CacheKeyInputs(const std::vector<std::string>& input_keys,
                                        const std::optional<VersionLink>& version) {
  std::vector<std::string> keys = input_keys;
  if (version && !version->predecessor_key.empty()) keys.push_back(version->predecessor_key);
  return keys;
}

std::optional<std::string> NewestGraphKey(ArtifactStore& store, const std::string& map_name) {
  const StageDefinition& final_stage = StageOf(FinalStage());
  const std::optional<std::string> final_key = store.ReadHeadKey(map_name, final_stage.info.name);
  if (final_stage.inputs.empty()) return final_key;
  const std::optional<std::string> input_key =
      store.ReadHeadKey(map_name, final_stage.inputs.front().name);
  if (!final_key || !input_key) return final_key ? final_key : input_key;
  const std::optional<ArtifactRecord> made = store.ReadArtifactSummary(map_name, *final_key);
  // A head that cannot be reached by its key is damage, never a reason to
  // fall back to the graph without stable ids.
  if (!made) {
    throw StoreError(std::string("the ") + final_stage.info.name + " head " + ShortKey(*final_key) +
                     " of map '" + map_name +
                     "' cannot be found by its key: the store is damaged (ag-store verify lists "
                     "the damage)");
  }
  const bool current = std::find(made->input_keys.begin(), made->input_keys.end(), *input_key) !=
                       made->input_keys.end();
  return current ? final_key : input_key;
}

}  // namespace areagraph
