#include "stages/pipeline/map_pipeline.h"

#include <memory>

#include "proto/artifacts.pb.h"
#include "stages/clean/clean_stage.h"
#include "stages/cut/cut_graph_builder.h"
#include "stages/merge/area_graph_builder.h"
#include "stages/prune/topology_graph_builder.h"
#include "stages/voronoi/voronoi_stage.h"

namespace areagraph {
namespace {

StageInputs InputsOf(std::vector<std::string> keys) {
  StageInputs inputs;
  inputs.digests = std::move(keys);
  return inputs;
}

}  // namespace

void RunMapPipeline(ArtifactStore& store, const std::string& map_name,
                    const proto::PipelineOptions& options, bool force,
                    const std::function<void(const StageInfo&, const StageRun&)>& on_stage) {
  std::string grid_key, cleaned_key, diagram_key, topology_key, cut_key;
  const auto grid = ReadHeadArtifact<proto::GridMap>(store, map_name, kImportStage, &grid_key);
  on_stage(kCleanStage, RunCachedStage(
                            store, map_name, kCleanStage, options.clean(), InputsOf({grid_key}),
                            [&] {
                              return std::make_unique<proto::CleanedMap>(
                                  CleanGridMap(grid, options.clean(), map_name));
                            },
                            force));
  const auto cleaned =
      ReadHeadArtifact<proto::CleanedMap>(store, map_name, kCleanStage, &cleaned_key);

  on_stage(kVoronoiStage,
           RunCachedStage(
               store, map_name, kVoronoiStage, options.voronoi(), InputsOf({cleaned_key}),
               [&] {
                 return std::make_unique<proto::VoronoiDiagram>(
                     ComputeVoronoiStage(cleaned, options.voronoi(), map_name));
               },
               force));
  const auto diagram =
      ReadHeadArtifact<proto::VoronoiDiagram>(store, map_name, kVoronoiStage, &diagram_key);

  on_stage(kPruneStage,
           RunCachedStage(
               store, map_name, kPruneStage, options.prune(), InputsOf({diagram_key, cleaned_key}),
               [&] {
                 return std::make_unique<proto::TopologyGraph>(
                     BuildTopologyGraph(diagram, cleaned, options.prune(), map_name));
               },
               force));
  const auto topology =
      ReadHeadArtifact<proto::TopologyGraph>(store, map_name, kPruneStage, &topology_key);

  on_stage(kCutStage,
           RunCachedStage(
               store, map_name, kCutStage, options.cut(), InputsOf({topology_key, cleaned_key}),
               [&] {
                 return std::make_unique<proto::CutGraph>(
                     BuildCutGraph(topology, cleaned, options.cut(), map_name));
               },
               force));
  const auto cut = ReadHeadArtifact<proto::CutGraph>(store, map_name, kCutStage, &cut_key);

  on_stage(kMergeStage,
           RunCachedStage(
               store, map_name, kMergeStage, options.merge(), InputsOf({cut_key, cleaned_key}),
               [&] {
                 return std::make_unique<proto::AreaGraph>(
                     BuildAreaGraph(cut, cleaned, options.merge(), map_name));
               },
               force));
}

}  // namespace areagraph
