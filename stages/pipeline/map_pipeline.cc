#include "stages/pipeline/map_pipeline.h"

#include "common/error.h"
#include "stages/geometry/site_triangulation.h"
#include "stages/pipeline/stage_versions.h"

namespace areagraph {
namespace {

// Position of `stage` in PipelineStages(); throws OptionsError for import.
size_t StepIndex(const std::vector<StageInfo>& stages, const StageInfo& stage) {
  for (size_t i = 0; i < stages.size(); ++i) {
    if (SameStage(stages[i], stage)) return i;
  }
  throw OptionsError("'" + std::string(stage.name) + "' is not a stage after import");
}

// True when one of stages[from, end) reads `input`'s artifact.
bool ReadLater(const std::vector<StageInfo>& stages, size_t from, size_t end,
               const StageInfo& input) {
  for (size_t i = from; i < end; ++i) {
    for (const StageInfo& read : StageOf(stages[i]).inputs) {
      if (SameStage(read, input)) return true;
    }
  }
  return false;
}

}  // namespace

std::vector<std::string> PlanPipelineKeys(const std::string& import_key,
                                          const proto::PipelineOptions& options,
                                          const PreviousVersionLookup& previous) {
  const std::vector<StageInfo> stages = PipelineStages();
  std::vector<std::string> keys;
  for (const StageInfo& info : stages) {
    const StageDefinition& stage = StageOf(info);
    std::vector<std::string> input_keys;
    for (const StageInfo& input : stage.inputs) {
      input_keys.push_back(StageOf(input).inputs.empty() ? import_key
                                                         : keys[StepIndex(stages, input)]);
    }
    std::optional<VersionLink> version;
    if (stage.reads_previous_version()) {
      version = previous ? previous(stage, input_keys) : VersionLink{};
    }
    keys.push_back(
        StageCacheKey(info, stage.options_of(options), CacheKeyInputs(input_keys, version)));
  }
  return keys;
}

void RunMapPipeline(ArtifactStore& store, const std::string& map_name,
                    const proto::PipelineOptions& options, bool force,
                    const PipelineObserver& observer, const StageInfo& first, const StageInfo& last,
                    ArtifactMemo* memo) {
  ArtifactMemo own_memo;
  if (memo == nullptr) memo = &own_memo;
  // What voronoi kept for a prune that did not run (cached, failed, --to
  // voronoi) goes with the run, not with the next map.
  struct DropKeptTriangulation {
    ~DropKeptTriangulation() { DropSiteTriangulation(); }
  } drop_kept_triangulation;
  const std::vector<StageInfo> stages = PipelineStages();
  const size_t end = StepIndex(stages, last) + 1;
  for (size_t i = StepIndex(stages, first); i < end; ++i) {
    if (observer.on_start) observer.on_start(stages[i]);
    for (const StageInfo& input : StageOf(stages[i]).inputs) {
      if (!ReadLater(stages, i + 1, end, input)) memo->MarkLastRead(input.name);
    }
    const StageRun run = RunStageOnHeads(store, map_name, StageOf(stages[i]), options, force, memo,
                                         observer.between_steps);
    if (observer.on_done) observer.on_done(stages[i], run);
    // The last stage's artifact stays for the caller (ag-run's summary).
    for (const StageDefinition& stage : StageTable()) {
      if (!SameStage(stage.info, last) && !ReadLater(stages, i + 1, end, stage.info)) {
        memo->Forget(stage.info.name);
      }
    }
  }
  store.FinishWrites();
}

void RunMapPipeline(ArtifactStore& store, const std::string& map_name,
                    const proto::PipelineOptions& options, bool force,
                    const std::function<void(const StageInfo&, const StageRun&)>& on_stage) {
  const std::vector<StageInfo> stages = PipelineStages();
  RunMapPipeline(store, map_name, options, force, PipelineObserver{nullptr, on_stage, nullptr},
                 stages.front(), stages.back());
}

}  // namespace areagraph
