#include "stages/pipeline/stage.h"

#include <chrono>
#include <exception>
#include <new>

#include "common/error.h"
#include "common/text.h"
#include "stages/common/pipeline_options.h"
#include "stages/pipeline/stage_versions.h"

namespace areagraph {
namespace {

InputError MissingInput(ArtifactStore& store, const std::string& map_name, const StageInfo& stage) {
  if (!store.ReadMap(map_name)) {
    return InputError("map '" + map_name + "' is not in the store; run ag-import first");
  }
  return InputError("map '" + map_name + "' has no " + stage.name + " artifact; run ag-" +
                    stage.name + " first");
}

// The artifact's type name as the store records it: the stage table's name
// for a type a stage writes (protobuf's descriptors, which GetTypeName
// builds, cost a short reader such as ag-render 0.9 M instructions), else
// GetTypeName.
std::string TypeName(const google::protobuf::Message& artifact) {
  const StageDefinition* stage = StageWritingType(artifact);
  return stage != nullptr ? stage->proto_type : artifact.GetTypeName();
}

// Whether the stored artifact is of `message`'s type.
bool IsOfType(const ArtifactRecord& record, const google::protobuf::Message& message) {
  return record.proto_type == TypeName(message);
}

// A cache hit's summary: from the row, or (for an artifact stored before the
// store kept summary lines) from the parsed payload.
std::string SummaryOfStored(ArtifactStore& store, const std::string& map_name,
                            const StageDefinition& stage, const std::string& cache_key) {
  const std::optional<ArtifactRecord> row = store.ReadArtifactSummary(map_name, cache_key);
  if (row && !row->summary_line.empty()) return row->summary_line;
  MessagePtr artifact(stage.prototype->New());
  ParseArtifact(store, map_name, cache_key, artifact.get());
  return stage.summarize(*artifact);
}

StageRun ComputeAndStore(ArtifactStore& store, const std::string& map_name,
                         const StageDefinition& stage, const google::protobuf::Message& options,
                         const StageInputs& inputs, const std::function<MessagePtr()>& compute,
                         StageRun run, ArtifactMemo* memo) {
  const auto start = std::chrono::steady_clock::now();
  MessagePtr result = compute();
  run.elapsed_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  run.summary = stage.summarize(*result);

  NewArtifact artifact;
  artifact.map_name = map_name;
  artifact.stage = stage.info.name;
  artifact.cache_key = run.cache_key;
  artifact.input_keys = inputs.digests;
  artifact.options_text = CanonicalText(options);
  artifact.stage_version = stage.info.version;
  artifact.proto_type = TypeName(*result);
  artifact.elapsed_ms = run.elapsed_ms;
  artifact.summary_line = run.summary;
  artifact.source_path = inputs.source_path;
  artifact.source_digest = inputs.source_digest;
  artifact.version = inputs.version;
  // A write-behind store finishes the write while the next stage computes;
  // the result is not changed meanwhile (see the take below).
  std::shared_ptr<const google::protobuf::Message> shared(std::move(result));
  store.WriteSharedMessageArtifact(std::move(artifact), shared);
  if (memo != nullptr) memo->Keep(stage.info.name, run.cache_key, std::move(shared));
  return run;
}

}  // namespace

StageRun RunCachedStage(ArtifactStore& store, const std::string& map_name,
                        const StageDefinition& stage, const proto::PipelineOptions& options,
                        const StageInputs& inputs, const std::function<MessagePtr()>& compute,
                        bool force, ArtifactMemo* memo) {
  const google::protobuf::Message& stage_options = stage.options_of(options);
  StageRun run;
  run.cache_key =
      StageCacheKey(stage.info, stage_options, CacheKeyInputs(inputs.digests, inputs.version));
  try {
    try {
      if (!force) {
        // Key lookups only: a hit costs no payload read. A damaged payload
        // shows when a later stage reads it (or with ag-store verify).
        const bool is_head = store.ReadHeadKey(map_name, stage.info.name) == run.cache_key;
        if (is_head || store.HasArtifact(map_name, run.cache_key)) {
          if (!is_head) store.UpdateHead(map_name, run.cache_key);
          run.cache_hit = true;
          run.summary = SummaryOfStored(store, map_name, stage, run.cache_key);
          return run;
        }
      }
      return ComputeAndStore(store, map_name, stage, stage_options, inputs, compute, run, memo);
    } catch (...) {
      // An earlier stage's write that failed meanwhile (write_behind_store.h)
      // is the error: run one by one, it would have stopped the map first.
      store.FinishWrites();
      throw;
    }
  } catch (const MapStepError&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw MapStepError(map_name, stage.info.name, "out of memory");
  } catch (const std::exception& error) {
    throw MapStepError(map_name, stage.info.name, error.what());
  }
}

StageRun RunStageOnHeads(ArtifactStore& store, const std::string& map_name,
                         const StageDefinition& stage, const proto::PipelineOptions& options,
                         bool force, ArtifactMemo* memo,
                         const std::function<void()>& between_steps) {
  StageInputs inputs = HeadInputs(store, map_name, stage);
  if (stage.reads_previous_version()) {
    inputs.version = PreviousVersionOf(store, map_name, stage, options, inputs.digests);
  }
  return RunCachedStage(
      store, map_name, stage, options, inputs,
      [&] {
        // Shared with the memo, or handed over by it when this stage is
        // the input's last reader: then `release` frees it.
        std::vector<std::shared_ptr<const google::protobuf::Message>> held;
        std::vector<const google::protobuf::Message*> views;
        for (size_t i = 0; i < stage.inputs.size(); ++i) {
          held.push_back(memo != nullptr ? memo->Acquire(stage.inputs[i].name, inputs.digests[i])
                                         : nullptr);
          if (held[i] == nullptr) {
            MessagePtr parsed(StageOf(stage.inputs[i]).prototype->New());
            ParseArtifact(store, map_name, inputs.digests[i], parsed.get());
            held[i] = std::move(parsed);
          }
          views.push_back(held[i].get());
        }
        if (!stage.reads_previous_version()) {
          const InputRelease release(
              [&](size_t i) {
                views.at(i) = nullptr;
                held.at(i).reset();
              },
              [&](size_t i) -> std::shared_ptr<google::protobuf::Message> {
                // A pending write of the input may hold it too, until it ends.
                if (held.at(i).use_count() != 1) store.FinishWrites();
                if (held.at(i).use_count() != 1) return nullptr;
                // Made as a mutable message (parsed, or a stage's result in
                // the memo); only `held` refers to it.
                return std::const_pointer_cast<google::protobuf::Message>(std::move(held[i]));
              },
              between_steps);
          return stage.compute(views, release, options);
        }
        MessagePtr previous;
        if (!inputs.version->predecessor_key.empty()) {
          previous.reset(stage.prototype->New());
          ParseArtifact(store, map_name, inputs.version->predecessor_key, previous.get());
        }
        return stage.compute_next_version(views, previous.get(), *inputs.version, options);
      },
      force, memo);
}

StageInputs HeadInputs(ArtifactStore& store, const std::string& map_name,
                       const StageDefinition& stage) {
  StageInputs inputs;
  for (const StageInfo& input : stage.inputs) {
    std::optional<std::string> key = store.ReadHeadKey(map_name, input.name);
    if (!key) {
      throw MapStepError(
          map_name, stage.info.name,
          store.ReadMap(map_name)
              ? "no " + std::string(input.name) + " artifact; run ag-" + input.name + " first"
              : "the map is not in the store; run ag-import first");
    }
    inputs.digests.push_back(*key);
  }
  return inputs;
}

void CheckFormatVersion(const google::protobuf::Message& artifact, const std::string& what) {
  const StageDefinition* stage = StageWritingType(artifact);
  if (stage == nullptr) return;
  const uint32_t version = stage->format_version_of(artifact);
  if (version > stage->format_version) {
    throw StoreError(what + " has format version " + std::to_string(version) +
                     ", newer than this build's " + std::to_string(stage->format_version) +
                     "; upgrade areagraph");
  }
}

void ParseArtifact(ArtifactStore& store, const std::string& map_name, const std::string& cache_key,
                   google::protobuf::Message* message) {
  const std::optional<ArtifactRecord> record = store.ReadArtifact(map_name, cache_key);
  if (!record || !IsOfType(*record, *message) || !message->ParseFromString(record->payload)) {
    throw StoreError("artifact " + ShortKey(cache_key) + " of map '" + map_name +
                     "' is missing or not a valid " + message->GetTypeName());
  }
  CheckFormatVersion(*message, "artifact " + ShortKey(cache_key) + " of map '" + map_name + "'");
}

void ParseHeadArtifact(ArtifactStore& store, const std::string& map_name, const StageInfo& stage,
                       google::protobuf::Message* message, std::string* cache_key) {
  const std::optional<ArtifactRecord> head = store.ReadHead(map_name, stage.name);
  if (!head) throw MissingInput(store, map_name, stage);
  if (!IsOfType(*head, *message) || !message->ParseFromString(head->payload)) {
    throw StoreError("the " + std::string(stage.name) + " artifact of map '" + map_name +
                     "' is not a valid " + message->GetTypeName());
  }
  CheckFormatVersion(*message,
                     "the " + std::string(stage.name) + " artifact of map '" + map_name + "'");
  if (cache_key != nullptr) *cache_key = head->cache_key;
}

}  // namespace areagraph
