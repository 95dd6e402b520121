#include "runner/common/map_run.h"

#include <exception>
#include <memory>
#include <new>
#include <optional>

#include "common/error.h"
#include "common/process_setup/freed_memory.h"
#include "stages/pipeline/stage_versions.h"

namespace areagraph {
namespace {

// Runs `step` of `map_name`, adding where it failed to any error.
template <typename Step>
auto InStep(const std::string& map_name, const std::string& step, Step&& body) {
  try {
    return body();
  } catch (const MapStepError&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw MapStepError(map_name, step, "out of memory");
  } catch (const std::exception& error) {
    throw MapStepError(map_name, step, error.what());
  }
}

// Without --from/--only/--force: every key follows from the import's inputs
// and the options; when all are stored, the heads are set without any
// artifact being read. Returns false when something must run.
bool SetHeadsIfFullyCached(ArtifactStore& store, const std::string& map_name,
                           const StageInputs& inputs, const proto::PipelineOptions& options,
                           const PipelineObserver& observer) {
  const StageDefinition& import = StageOf(kImportStage);
  std::vector<std::pair<StageInfo, std::string>> keys = {
      {kImportStage, StageCacheKey(kImportStage, import.options_of(options), inputs.digests)}};
  const std::vector<std::string> planned =
      PlanPipelineKeys(keys[0].second, options,
                       [&](const StageDefinition& stage, const std::vector<std::string>& in) {
                         return PreviousVersionOf(store, map_name, stage, options, in);
                       });
  const std::vector<StageInfo> stages = PipelineStages();
  for (size_t i = 0; i < planned.size(); ++i) keys.emplace_back(stages[i], planned[i]);
  for (const auto& [stage, key] : keys) {
    if (!store.HasArtifact(map_name, key)) return false;
  }
  for (const auto& [stage, key] : keys) {
    if (store.ReadHeadKey(map_name, stage.name) != key) store.UpdateHead(map_name, key);
    StageRun run;
    run.cache_key = key;
    run.cache_hit = true;
    if (observer.on_done) observer.on_done(stage, run);
  }
  return true;
}

// Runs the map's stages; `memo` then holds the last stage's artifact when it
// was computed here.
void RunStages(ArtifactStore& store, const std::string& map_name, const MapImport& import,
               const proto::PipelineOptions& options, const MapRunSettings& settings,
               const PipelineObserver& observer, ArtifactMemo& memo) {
  const std::vector<StageInfo> stages = PipelineStages();
  StageInfo first = settings.first;
  if (SameStage(first, kImportStage)) {
    const StageInputs inputs = InStep(map_name, kImportStage.name, import.read_inputs);
    const bool whole_pipeline = SameStage(settings.last, stages.back());
    if (!settings.force && whole_pipeline && InStep(map_name, kImportStage.name, [&] {
          return SetHeadsIfFullyCached(store, map_name, inputs, options, observer);
        })) {
      return;
    }
    if (observer.on_start) observer.on_start(kImportStage);
    const StageRun run = RunCachedStage(store, map_name, StageOf(kImportStage), options, inputs,
                                        import.decode, settings.force, &memo);
    if (observer.on_done) observer.on_done(kImportStage, run);
    if (SameStage(settings.last, kImportStage)) return;
    first = stages.front();
  }
  RunMapPipeline(store, map_name, options, settings.force, observer, first, settings.last, &memo);
  // Between stages the next one reuses what the last freed (giving it back
  // costs its pages' faults again: 15-20 % of lab_a 8 x 8's CPU); after the
  // map it goes back, so that a worker or ag-live does not keep its peak.
  ReturnFreedMemory();
}

// The head graph of the final stage and its key: the one just computed, as
// the memo holds it (equal to the stored bytes parsed), else read back.
std::shared_ptr<const proto::AreaGraph> FinalGraph(ArtifactStore& store,
                                                   const std::string& map_name, ArtifactMemo& memo,
                                                   std::string* key) {
  const StageInfo final_stage = FinalStage();
  const std::optional<std::string> head = store.ReadHeadKey(map_name, final_stage.name);
  if (head) {
    const auto computed =
        std::dynamic_pointer_cast<const proto::AreaGraph>(memo.Acquire(final_stage.name, *head));
    if (computed) {
      *key = *head;
      return computed;
    }
  }
  return std::make_shared<const proto::AreaGraph>(
      ReadHeadArtifact<proto::AreaGraph>(store, map_name, final_stage, key));
}

}  // namespace

FailureLog::FailureLog(ArtifactStore& store) : store_(store) {
  for (const FailureRecord& failure : store_.ReadFailures()) failed_maps_.insert(failure.map_name);
}

bool FailureLog::Record(const FailureRecord& failure) {
  try {
    store_.RecordFailure(failure);
    failed_maps_.insert(failure.map_name);
    return true;
  } catch (const std::exception&) {
    return false;  // the caller reports it some other way
  }
}

void FailureLog::ClearIfRecorded(const std::string& map_name) {
  if (failed_maps_.erase(map_name) > 0) store_.ClearFailure(map_name);
}

MapOutcome RunOneMap(ArtifactStore& store, FailureLog& failures, const std::string& map_name,
                     const std::string& source_path, const MapImport& import,
                     const proto::PipelineOptions& options, const MapRunSettings& settings,
                     const PipelineObserver& observer, const GraphPublisher& publish) {
  MapOutcome outcome;
  try {
    const StageInfo final_stage = FinalStage();
    const bool makes_graph = SameStage(settings.last, final_stage);
    const std::optional<std::string> old_graph =
        makes_graph ? store.ReadHeadKey(map_name, final_stage.name) : std::nullopt;
    PipelineObserver counting = observer;
    counting.between_steps = ReturnFreedMemory;
    counting.on_done = [&](const StageInfo& stage, const StageRun& run) {
      ++outcome.stages_run;
      outcome.cache_hits += run.cache_hit ? 1 : 0;
      outcome.compute_ms += run.elapsed_ms;
      if (observer.on_done) observer.on_done(stage, run);
    };
    ArtifactMemo memo;
    RunStages(store, map_name, import, options, settings, counting, memo);
    store.FinishWrites();  // the map is done once its artifacts are stored
    outcome.fully_cached = outcome.stages_run > 0 && outcome.cache_hits == outcome.stages_run;
    if (makes_graph) {
      std::string key;
      const std::shared_ptr<const proto::AreaGraph> final_graph =
          FinalGraph(store, map_name, memo, &key);
      const proto::AreaGraph& graph = *final_graph;
      outcome.areas = graph.areas_size();
      outcome.passages = graph.passages_size();
      outcome.components = graph.components();
      outcome.dropped_parts = graph.dropped_parts();
      outcome.graph_changed = old_graph != key;
      if (publish && (outcome.graph_changed || settings.publish_unchanged)) {
        InStep(map_name, "publish", [&] { publish(map_name, key, graph); });
        outcome.published = true;
      }
    }
    failures.ClearIfRecorded(map_name);
    outcome.ok = true;
  } catch (const MapStepError& error) {
    outcome.failed_step = error.step();
    outcome.error = error.cause();
  } catch (const std::exception& error) {
    outcome.error = error.what();
  }
  if (!outcome.ok) {
    outcome.failure_recorded =
        failures.Record({map_name, outcome.failed_step, outcome.error, source_path, ""});
  }
  return outcome;
}

}  // namespace areagraph
