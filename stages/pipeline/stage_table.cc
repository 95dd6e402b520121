#include "stages/pipeline/stage_table.h"

#include <cstdarg>
#include <cstdio>
#include <typeinfo>

#include "common/error.h"
#include "proto/artifacts.pb.h"
#include "stages/clean/clean_stage.h"
#include "stages/common/grid_cells.h"
#include "stages/common/voronoi_arrays.h"
#include "stages/cut/cut_graph_builder.h"
#include "stages/match/area_graph_matching.h"
#include "stages/merge/area_graph_builder.h"
#include "stages/prune/topology_graph_builder.h"
#include "stages/voronoi/voronoi_stage.h"

namespace areagraph {
namespace {

using google::protobuf::Message;
using Inputs = std::vector<const Message*>;

// Input `i` of a compute function, as the type its stage writes.
template <typename T>
const T& Input(const Inputs& inputs, size_t i) {
  return static_cast<const T&>(*inputs.at(i));
}

// The format_version of an artifact of type T, read without protobuf's
// reflection.
template <typename T>
uint32_t FormatVersionOf(const Message& artifact) {
  return static_cast<const T&>(artifact).format_version();
}

template <typename T>
MessagePtr Wrap(T message) {
  return std::make_unique<T>(std::move(message));
}

std::string Printf(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string Printf(const char* format, ...) {
  char line[256];
  va_list args;
  va_start(args, format);
  std::vsnprintf(line, sizeof(line), format, args);
  va_end(args);
  return line;
}

std::string SummarizeGridMap(const Message& artifact) {
  const auto& grid = static_cast<const proto::GridMap&>(artifact);
  const CellCounts counts = CountCells(grid.cells());
  return Printf("%dx%d px, %g m/px, %lld occupied, %lld free, %lld unknown",
                grid.frame().width_px(), grid.frame().height_px(), grid.frame().resolution_m(),
                static_cast<long long>(counts.occupied), static_cast<long long>(counts.free),
                static_cast<long long>(counts.unknown));
}

std::string SummarizeCleanedMap(const Message& artifact) {
  const auto& cleaned = static_cast<const proto::CleanedMap&>(artifact);
  return Printf("%d outlier cells, %d furniture cells in %d pieces removed",
                cleaned.removed_outlier_cells_size(), cleaned.removed_furniture_cells_size(),
                cleaned.furniture_shapes_size());
}

std::string SummarizeVoronoiDiagram(const Message& artifact) {
  const auto& diagram = static_cast<const proto::VoronoiDiagram&>(artifact);
  return Printf("%d sites, %d vertices, %d edges", VoronoiSiteCount(diagram),
                VoronoiVertexCount(diagram), VoronoiEdgeCount(diagram));
}

std::string SummarizeTopologyGraph(const Message& artifact) {
  const auto& graph = static_cast<const proto::TopologyGraph&>(artifact);
  return Printf("%d vertices, %d edges, %d parts (%d smaller dropped)", graph.vertices_size(),
                graph.edges_size(), graph.parts(), graph.dropped_parts());
}

std::string SummarizeCutGraph(const Message& artifact) {
  const auto& graph = static_cast<const proto::CutGraph&>(artifact);
  return Printf("W = %.2f m%s, %d rooms, %d passage points, %d edges",
                graph.room_width().room_width_m(), graph.room_width().automatic() ? " (auto)" : "",
                graph.room_shapes_size(), graph.passage_points_size(), graph.edges_size());
}

std::string SummarizeAreaGraph(const Message& artifact) {
  const auto& graph = static_cast<const proto::AreaGraph&>(artifact);
  return Printf("%d areas, %d passages, %d components, %d parts dropped", graph.areas_size(),
                graph.passages_size(), graph.components(), graph.dropped_parts());
}

std::vector<StageDefinition> MakeStageTable() {
  std::vector<StageDefinition> table;
  table.push_back({
      kImportStage,
      {},
      [](const proto::PipelineOptions& o) -> const Message& { return o.import(); },
      &proto::GridMap::default_instance(),
      kGridMapFormatVersion,
      "areagraph.proto.GridMap",
      FormatVersionOf<proto::GridMap>,
      nullptr,  // reads a file: see ag-import and runner/common
      SummarizeGridMap,
      "Decodes a map image into occupied, free and unknown cells and stores it as the map's "
      "GridMap.",
  });
  table.push_back({
      kCleanStage,
      {kImportStage},
      [](const proto::PipelineOptions& o) -> const Message& { return o.clean(); },
      &proto::CleanedMap::default_instance(),
      kCleanedMapFormatVersion,
      "areagraph.proto.CleanedMap",
      FormatVersionOf<proto::CleanedMap>,
      [](const Inputs& in, const InputRelease&, const proto::PipelineOptions& o) {
        return Wrap(CleanGridMap(Input<proto::GridMap>(in, 0), o.clean()));
      },
      SummarizeCleanedMap,
      "Removes outliers (CGAL remove_outliers) and furniture (small alpha-shape pieces) from a "
      "map's head GridMap (run ag-import first) and stores the result as a CleanedMap.",
  });
  table.push_back({
      kVoronoiStage,
      {kCleanStage},
      [](const proto::PipelineOptions& o) -> const Message& { return o.voronoi(); },
      &proto::VoronoiDiagram::default_instance(),
      kVoronoiDiagramFormatVersion,
      "areagraph.proto.VoronoiDiagram",
      FormatVersionOf<proto::VoronoiDiagram>,
      [](const Inputs& in, const InputRelease&, const proto::PipelineOptions& o) {
        return Wrap(ComputeVoronoiStage(Input<proto::CleanedMap>(in, 0), o.voronoi()));
      },
      SummarizeVoronoiDiagram,
      "Computes the Voronoi diagram of the obstacle cells next to free space of a map's head "
      "CleanedMap (run ag-clean first) and stores it as a VoronoiDiagram.",
  });
  table.push_back({
      kPruneStage,
      {kVoronoiStage, kCleanStage},
      [](const proto::PipelineOptions& o) -> const Message& { return o.prune(); },
      &proto::TopologyGraph::default_instance(),
      kTopologyGraphFormatVersion,
      "areagraph.proto.TopologyGraph",
      FormatVersionOf<proto::TopologyGraph>,
      [](const Inputs& in, const InputRelease& release, const proto::PipelineOptions& o) {
        return Wrap(BuildTopologyGraph(Input<proto::VoronoiDiagram>(in, 0),
                                       Input<proto::CleanedMap>(in, 1), o.prune(),
                                       [&] { release(0); }));
      },
      SummarizeTopologyGraph,
      "Prunes a map's head VoronoiDiagram (run ag-voronoi first) into the Topology Graph: "
      "boundary alpha shape, clearance filter, dead-end removal with the polygons joined (the "
      "paper's Alg. 2), the biggest connected part and every other part of at least "
      "prune.min_component_m2 (the smaller ones are counted), and beside a part's longest graph "
      "every other of at least prune.keep_groups_above_m. Stores a TopologyGraph.",
  });
  table.push_back({
      kCutStage,
      {kPruneStage, kCleanStage},
      [](const proto::PipelineOptions& o) -> const Message& { return o.cut(); },
      &proto::CutGraph::default_instance(),
      kCutGraphFormatVersion,
      "areagraph.proto.CutGraph",
      FormatVersionOf<proto::CutGraph>,
      [](const Inputs& in, const InputRelease& release, const proto::PipelineOptions& o) {
        // When the graph is this stage's alone, cut takes its edges over.
        const auto owned = std::static_pointer_cast<proto::TopologyGraph>(release.TakeInput(0));
        return Wrap(BuildCutGraph(Input<proto::TopologyGraph>(in, 0),
                                  Input<proto::CleanedMap>(in, 1), o.cut(), owned.get(),
                                  release.between_steps()));
      },
      SummarizeCutGraph,
      "Detects rooms (alpha shapes with alpha = (W/2)^2; W estimated from the map's doors and "
      "corridors with cut.room_width_m=auto, the default, else cut.room_width_m or the "
      "door/corridor strategy) and cuts the edges of a map's head TopologyGraph (run ag-prune "
      "first) where they leave a room (the paper's Alg. 3). Stores a CutGraph with W and the "
      "doors and corridors found (ag-inspect --stage cut).",
  });
  table.push_back({
      kMergeStage,
      {kCutStage, kCleanStage},
      [](const proto::PipelineOptions& o) -> const Message& { return o.merge(); },
      &proto::AreaGraph::default_instance(),
      kAreaGraphFormatVersion,
      "areagraph.proto.AreaGraph",
      FormatVersionOf<proto::AreaGraph>,
      [](const Inputs& in, const InputRelease&, const proto::PipelineOptions& o) {
        return Wrap(BuildAreaGraph(Input<proto::CutGraph>(in, 0), Input<proto::CleanedMap>(in, 1),
                                   o.merge()));
      },
      SummarizeAreaGraph,
      "Merges the edges of a map's head CutGraph (run ag-cut first) into areas: one per room, "
      "one per room-less edge. Splits the free space among them, traces their polygons and "
      "finds the passages between them. Stores the AreaGraph.",
  });
  table.push_back({
      kMatchStage,
      {kMergeStage},
      [](const proto::PipelineOptions& o) -> const Message& { return o.match(); },
      &proto::AreaGraph::default_instance(),
      kAreaGraphFormatVersion,
      "areagraph.proto.AreaGraph",
      FormatVersionOf<proto::AreaGraph>,
      nullptr,  // reads its previous version: compute_next_version
      SummarizeAreaGraph,
      "Gives the areas and passages of a map's head AreaGraph (run ag-merge first) ids that stay "
      "stable across the map's versions: each area is matched by overlap to the previous "
      "version (this stage's head before the run), a split keeping the id on its largest part "
      "and a merge that of its largest parent; new areas get ids never used before. Stores the "
      "AreaGraph with stable ids as the map's next version (ag-inspect --history).",
      [](const Inputs& in, const Message* previous, const VersionLink& version,
         const proto::PipelineOptions& o) {
        return Wrap(MatchAreaGraph(Input<proto::AreaGraph>(in, 0),
                                   static_cast<const proto::AreaGraph*>(previous), version,
                                   o.match(), SegmentationOptionsDigest(o)));
      },
  });
  return table;
}

}  // namespace

const std::vector<StageDefinition>& StageTable() {
  static const std::vector<StageDefinition> table = MakeStageTable();
  return table;
}

const StageDefinition& StageOf(const StageInfo& stage) { return FindStage(stage.name); }

const StageDefinition& FindStage(const std::string& name, const std::string& what) {
  for (const StageDefinition& stage : StageTable()) {
    if (name == stage.info.name) return stage;
  }
  throw OptionsError(what + " '" + name + "' is not a stage; stages: " + StageNameList());
}

std::string StageNameList() {
  std::string list;
  for (const StageDefinition& stage : StageTable()) {
    list += (list.empty() ? "" : ", ") + std::string(stage.info.name);
  }
  return list;
}

std::vector<StageInfo> PipelineStages() {
  std::vector<StageInfo> stages;
  for (const StageDefinition& stage : StageTable()) {
    if (!stage.inputs.empty()) stages.push_back(stage.info);
  }
  return stages;
}

const StageInfo& FinalStage() { return StageTable().back().info; }

std::vector<std::string> FileInputStageNames() {
  std::vector<std::string> names;
  for (const StageDefinition& stage : StageTable()) {
    if (stage.inputs.empty()) names.push_back(stage.info.name);
  }
  return names;
}

MessagePtr NewArtifactMessage(const std::string& proto_type) {
  for (const StageDefinition& stage : StageTable()) {
    if (stage.proto_type == proto_type) return MessagePtr(stage.prototype->New());
  }
  return nullptr;
}

const StageDefinition* StageWritingType(const google::protobuf::Message& artifact) {
  for (const StageDefinition& stage : StageTable()) {
    if (typeid(*stage.prototype) == typeid(artifact)) return &stage;
  }
  return nullptr;
}

std::string SummarizeArtifact(const google::protobuf::Message& artifact) {
  const StageDefinition* stage = StageWritingType(artifact);
  if (stage == nullptr) throw Error("no stage writes artifacts of type " + artifact.GetTypeName());
  return stage->summarize(artifact);
}

}  // namespace areagraph
