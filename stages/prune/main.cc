// ag-prune: the Topology Graph with polygons from a map's Voronoi diagram.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>

#include "stages/common/command_line.h"
#include "stages/common/stage.h"
#include "stages/prune/topology_graph_builder.h"
#include "store/artifact_store.h"

using namespace areagraph;

int main(int argc, char** argv) {
  CLI::App app{
      "Prunes a map's head VoronoiDiagram (run ag-voronoi first) into the Topology Graph: "
      "boundary alpha shape, clearance filter, dead-end removal with the polygons joined "
      "(the paper's Alg. 2), the biggest connected part and every other part of at least "
      "prune.min_component_m2 (the smaller ones are counted). Stores a TopologyGraph."};
  StageCommandLine flags;
  AddStageFlags(app, flags);
  return RunCommand("ag-prune", app, argc, argv, [&] {
    const proto::PipelineOptions options = LoadPipelineOptions(flags);
    CheckPruneOptions(options.prune());
    const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(flags.store_path);
    const StageInputs inputs = HeadInputs(*store, flags.map_name, kPruneStage);
    const StageRun run = RunCachedStage(
        *store, flags.map_name, kPruneStage, options.prune(), inputs,
        [&] {
          return std::make_unique<proto::TopologyGraph>(BuildTopologyGraph(
              ReadArtifactAs<proto::VoronoiDiagram>(*store, flags.map_name, inputs.digests[0]),
              ReadArtifactAs<proto::CleanedMap>(*store, flags.map_name, inputs.digests[1]),
              options.prune(), flags.map_name));
        },
        flags.force);
    const auto graph = ReadHeadArtifact<proto::TopologyGraph>(*store, flags.map_name, kPruneStage);
    std::printf(
        "ag-prune: map '%s': %d vertices, %d edges, %d parts (%d smaller dropped), %.0f ms, key "
        "%.12s (%s)\n",
        flags.map_name.c_str(), graph.vertices_size(), graph.edges_size(), graph.parts(),
        graph.dropped_parts(), run.elapsed_ms, run.cache_key.c_str(),
        run.cache_hit ? "cached" : "computed");
    return 0;
  });
}
