#include "stages/pipeline/map_pipeline.h"

#include <memory>

#include "proto/artifacts.pb.h"
#include "stages/clean/clean_stage.h"
#include "stages/cut/cut_graph_builder.h"
#include "stages/merge/area_graph_builder.h"
#include "stages/prune/topology_graph_builder.h"
#include "stages/voronoi/voronoi_stage.h"
#include "store/error.h"

namespace areagraph {
namespace {

using MessagePtr = std::unique_ptr<google::protobuf::Message>;

// Computes one step from the input artifacts named by `keys` (InputStagesOf order).
MessagePtr ComputeStep(ArtifactStore& store, const std::string& map_name, const StageInfo& stage,
                       const std::vector<std::string>& keys,
                       const proto::PipelineOptions& options) {
  if (SameStage(stage, kCleanStage)) {
    return std::make_unique<proto::CleanedMap>(CleanGridMap(
        ReadArtifactAs<proto::GridMap>(store, map_name, keys[0]), options.clean(), map_name));
  }
  // Every later step reads the cleaned map, last among its inputs.
  const auto cleaned = ReadArtifactAs<proto::CleanedMap>(store, map_name, keys.back());
  if (SameStage(stage, kVoronoiStage)) {
    return std::make_unique<proto::VoronoiDiagram>(
        ComputeVoronoiStage(cleaned, options.voronoi(), map_name));
  }
  if (SameStage(stage, kPruneStage)) {
    return std::make_unique<proto::TopologyGraph>(
        BuildTopologyGraph(ReadArtifactAs<proto::VoronoiDiagram>(store, map_name, keys[0]), cleaned,
                           options.prune(), map_name));
  }
  if (SameStage(stage, kCutStage)) {
    return std::make_unique<proto::CutGraph>(
        BuildCutGraph(ReadArtifactAs<proto::TopologyGraph>(store, map_name, keys[0]), cleaned,
                      options.cut(), map_name));
  }
  return std::make_unique<proto::AreaGraph>(
      BuildAreaGraph(ReadArtifactAs<proto::CutGraph>(store, map_name, keys[0]), cleaned,
                     options.merge(), map_name));
}

size_t StepIndex(const std::string& stage_name) {
  const std::vector<StageInfo>& stages = PipelineStages();
  for (size_t i = 0; i < stages.size(); ++i) {
    if (stage_name == stages[i].name) return i;
  }
  throw OptionsError("'" + stage_name + "' is not a stage after import");
}

}  // namespace

const std::vector<StageInfo>& PipelineStages() {
  static const std::vector<StageInfo> stages = [] {
    std::vector<StageInfo> list;
    for (const StageInfo& stage : kAllStages) {
      if (!InputStagesOf(stage).empty()) list.push_back(stage);
    }
    return list;
  }();
  return stages;
}

const google::protobuf::Message& StageOptionsOf(const proto::PipelineOptions& options,
                                                const StageInfo& stage) {
  if (SameStage(stage, kImportStage)) return options.import();
  if (SameStage(stage, kCleanStage)) return options.clean();
  if (SameStage(stage, kVoronoiStage)) return options.voronoi();
  if (SameStage(stage, kPruneStage)) return options.prune();
  if (SameStage(stage, kCutStage)) return options.cut();
  return options.merge();
}

std::vector<std::string> PlanPipelineKeys(const std::string& import_key,
                                          const proto::PipelineOptions& options) {
  std::vector<std::string> keys;
  auto key_of = [&](const StageInfo& stage) -> const std::string& {
    if (SameStage(stage, kImportStage)) return import_key;
    return keys[StepIndex(stage.name)];
  };
  for (const StageInfo& stage : PipelineStages()) {
    std::vector<std::string> input_keys;
    for (const StageInfo& input : InputStagesOf(stage)) input_keys.push_back(key_of(input));
    keys.push_back(StageCacheKey(stage, StageOptionsOf(options, stage), input_keys));
  }
  return keys;
}

void RunMapPipeline(ArtifactStore& store, const std::string& map_name,
                    const proto::PipelineOptions& options, bool force,
                    const PipelineObserver& observer, const std::string& first_stage,
                    const std::string& last_stage) {
  const std::vector<StageInfo>& stages = PipelineStages();
  const size_t first = StepIndex(first_stage), last = StepIndex(last_stage);
  for (size_t i = first; i <= last; ++i) {
    const StageInfo& stage = stages[i];
    if (observer.on_start) observer.on_start(stage);
    const StageInputs inputs = HeadInputs(store, map_name, stage);
    const StageRun run = RunCachedStage(
        store, map_name, stage, StageOptionsOf(options, stage), inputs,
        [&] { return ComputeStep(store, map_name, stage, inputs.digests, options); }, force);
    if (observer.on_done) observer.on_done(stage, run);
  }
}

void RunMapPipeline(ArtifactStore& store, const std::string& map_name,
                    const proto::PipelineOptions& options, bool force,
                    const std::function<void(const StageInfo&, const StageRun&)>& on_stage) {
  RunMapPipeline(store, map_name, options, force, PipelineObserver{nullptr, on_stage});
}

}  // namespace areagraph
