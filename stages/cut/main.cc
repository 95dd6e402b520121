// ag-cut: rooms from alpha shapes, and the Topology Graph's edges cut at them.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>

#include "stages/common/command_line.h"
#include "stages/common/stage.h"
#include "stages/cut/cut_graph_builder.h"
#include "stages/cut/room_width.h"
#include "store/artifact_store.h"

using namespace areagraph;

int main(int argc, char** argv) {
  CLI::App app{
      "Detects rooms (alpha shapes with alpha = (W/2)^2; W estimated from the map's doors and "
      "corridors with cut.room_width_m=auto, the default, else cut.room_width_m or the "
      "door/corridor strategy) and cuts the edges of a map's head TopologyGraph (run ag-prune "
      "first) where they leave a room (the paper's Alg. 3). Stores a CutGraph with W and the "
      "doors and corridors found (ag-inspect --stage cut)."};
  StageCommandLine flags;
  AddStageFlags(app, flags);
  return RunCommand("ag-cut", app, argc, argv, [&] {
    const proto::PipelineOptions options = LoadPipelineOptions(flags);
    const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(flags.store_path);
    std::string topology_key, map_key;
    const auto topology =
        ReadHeadArtifact<proto::TopologyGraph>(*store, flags.map_name, kPruneStage, &topology_key);
    const auto map =
        ReadHeadArtifact<proto::CleanedMap>(*store, flags.map_name, kCleanStage, &map_key);
    RoomWidthM(options.cut(), map.frame());  // bad options fail before any work
    StageInputs inputs;
    inputs.digests = {topology_key, map_key};
    const StageRun run = RunCachedStage(
        *store, flags.map_name, kCutStage, options.cut(), inputs,
        [&] {
          return std::make_unique<proto::CutGraph>(
              BuildCutGraph(topology, map, options.cut(), flags.map_name));
        },
        flags.force);
    const auto graph = ReadHeadArtifact<proto::CutGraph>(*store, flags.map_name, kCutStage);
    std::printf(
        "ag-cut: map '%s': W = %.2f m%s, %d rooms, %d passage points, %d edges, %.0f ms, key %.12s "
        "(%s)\n",
        flags.map_name.c_str(), graph.room_width().room_width_m(),
        graph.room_width().automatic() ? " (auto)" : "", graph.room_shapes_size(),
        graph.passage_points_size(), graph.edges_size(), run.elapsed_ms, run.cache_key.c_str(),
        run.cache_hit ? "cached" : "computed");
    return 0;
  });
}
