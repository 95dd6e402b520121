#include "stages/merge/area_graph_builder.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "common/error.h"
#include "stages/common/pipeline_options_check.h"
#include "stages/common/skipped_passes.h"
#include "stages/common/stage_info.h"
#include "stages/geometry/cell_grid.h"
#include "stages/geometry/disjoint_sets.h"
#include "stages/geometry/edge_polygon.h"
#include "stages/geometry/polygon_raster.h"
#include "stages/merge/area_assignment.h"
#include "stages/merge/area_graph_geometry.h"
#include "stages/merge/area_kinds.h"
#include "stages/merge/furniture_rows.h"
#include "stages/merge/merge_passes.h"
#include "stages/merge/small_area_folding.h"
#include "stages/merge/vertex_openings.h"

namespace areagraph {
namespace {

void CheckCutGraph(const proto::CutGraph& graph) {
  if (graph.edges_size() == 0) {
    throw InputError("no Area Graph: the cut graph has no edges");
  }
  for (const proto::GraphEdge& edge : graph.edges()) {
    const bool ok = edge.source() >= 0 && edge.source() < graph.vertices_size() &&
                    edge.target() >= 0 && edge.target() < graph.vertices_size() &&
                    edge.path_size() >= 2 && edge.left_sites_size() == edge.path_size() - 1 &&
                    edge.right_sites_size() == edge.path_size() - 1;
    if (!ok) {
      throw InputError("the CutGraph artifact is corrupt (edge " + std::to_string(edge.id()) + ")");
    }
  }
}

// The paths of areas that run through a vertex (two or more of their edge
// ends meet there), at every vertex where one does.
std::vector<std::pair<PointList, int>> ThroughPaths(const proto::CutGraph& graph,
                                                    const AreaPlan& plan) {
  std::vector<std::map<int, std::vector<int>>> ends(graph.vertices_size());
  for (int e = 0; e < graph.edges_size(); ++e) {
    ends[graph.edges(e).source()][plan.area_of_edge[e]].push_back(e);
    ends[graph.edges(e).target()][plan.area_of_edge[e]].push_back(e);
  }
  std::vector<std::pair<PointList, int>> paths;
  for (const auto& at_vertex : ends) {
    for (const auto& [area, edges] : at_vertex) {
      if (edges.size() < 2) continue;
      for (int e : edges) paths.emplace_back(ToPointList(graph.edges(e).path()), area);
    }
  }
  return paths;
}

// Connected components of areas joined by passages.
int CountComponents(const proto::AreaGraph& graph) {
  DisjointSets components(graph.areas_size());
  int count = graph.areas_size();
  for (const proto::Passage& passage : graph.passages()) {
    if (components.Union(passage.area_a(), passage.area_b())) --count;
  }
  return count;
}

// The free space split among the plan's areas (PartitionFreeSpace). The
// removed obstacles that areas must not cover are cleared from the boundary
// mask, which becomes the partition's domain, instead of a raster of their
// own; the paths are freed before the outlines are built.
AreaRaster PartitionedFreeSpace(const proto::CutGraph& graph, const proto::CleanedMap& map,
                                const CellGrid& grid, const AreaPlan& plan,
                                const proto::MergeOptions& options) {
  std::vector<std::vector<const proto::Polygon*>> polygons(plan.areas.size());
  std::vector<std::vector<PointList>> paths(plan.areas.size());
  for (size_t k = 0; k < plan.areas.size(); ++k) {
    for (int e : plan.areas[k].edges) {
      paths[k].push_back(ToPointList(graph.edges(e).path()));
      polygons[k].push_back(&graph.edges(e).polygon());
      for (const proto::Polygon& absorbed : graph.edges(e).absorbed()) {
        polygons[k].push_back(&absorbed);
      }
    }
  }
  cv::Mat domain = BoundaryMask(graph.part_boundaries(), graph.boundary(),
                                cv::Size(grid.width(), grid.height()));
  if (!options.cover_removed_obstacles()) {
    for (const auto* list : {&map.removed_outlier_cells(), &map.removed_furniture_cells()}) {
      for (const int index : *list) {
        if (index >= 0 && index < grid.width() * grid.height()) domain.data[index] = 0;
      }
    }
  }
  return PartitionFreeSpace(grid, std::move(domain), polygons, paths, ThroughPaths(graph, plan),
                            RunsStagePass(options, proto::MergeOptions::GROWTH_STOPS_AT_NARROW_GAPS)
                                ? map.robot_width_m() / grid.resolution_m()
                                : 0);
}

}  // namespace

proto::AreaGraph BuildAreaGraph(const proto::CutGraph& graph, const proto::CleanedMap& map,
                                const proto::MergeOptions& options, AreaRaster* raster_out) {
  CheckMergeOptions(options);
  const CellGrid grid(map);
  CheckCutGraph(graph);
  if (!map.has_robot_width_m()) {
    throw InputError(
        "the CleanedMap holds no robot width (written by clean 4 or older): run "
        "ag-clean again");
  }
  if (!graph.has_min_clearance_m()) {
    throw InputError(
        "the CutGraph holds no clearance (written by cut 13 or older): run ag-prune "
        "and ag-cut again");
  }
  if (!graph.has_island_max_length_m()) {
    throw InputError(
        "the CutGraph holds no island length (written by cut 15 or older): run ag-cut again");
  }
  CheckOutlineTolerance(options, graph.room_width().room_width_m());
  const double cell_m2 = grid.resolution_m() * grid.resolution_m();

  AreaPlan plan = AssignAreas(graph);
  cv::Mat rows;
  if (RunsStagePass(options, proto::MergeOptions::JOIN_FURNITURE_ROWS)) {
    rows = FurnitureRowCells(map, options.furniture_gaps().max_elongation());
    if (cv::countNonZero(rows) == 0) rows.release();
  }
  const MergeInput input{graph, map, grid, options, ClosedVertices(graph), rows};
  RunJoinPasses(input, &plan);
  AreaRaster raster = PartitionedFreeSpace(graph, map, grid, plan, options);
  const int64_t min_cells =
      std::max<int64_t>(1, static_cast<int64_t>(std::ceil(options.min_area_m2() / cell_m2)));
  FoldSmallAreas(graph, min_cells, &plan, &raster, KeptSmallAreas(input, plan, raster, min_cells));
  if (std::all_of(raster.cell_count.begin(), raster.cell_count.end(),
                  [](int64_t n) { return n == 0; })) {
    throw InputError("no Area Graph: no free cell lies inside the map's boundary");
  }

  proto::AreaGraph out;
  out.set_format_version(kAreaGraphFormatVersion);
  *out.mutable_frame() = map.frame();
  // Rows of seats do not make a hall a corridor.
  SetAreaKinds(graph, raster, grid.resolution_m(), &plan, rows);
  // Without a caller for the raster, its labels (4 bytes a cell) go once
  // the borders are traced, before they are simplified.
  AddAreasAndPassages(graph, plan, raster, options, &out, [&] {
    if (raster_out == nullptr) raster.labels.release();
  });
  out.set_components(CountComponents(out));
  out.set_dropped_parts(graph.dropped_parts());
  out.set_dropped_area_m2(graph.dropped_area_m2());
  out.set_robot_width_m(map.robot_width_m());
  if (raster_out != nullptr) *raster_out = std::move(raster);
  return out;
}

}  // namespace areagraph
