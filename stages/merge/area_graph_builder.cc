#include "stages/merge/area_graph_builder.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "common/error.h"
#include "stages/common/pipeline_options_check.h"
#include "stages/common/stage_info.h"
#include "stages/geometry/cell_grid.h"
#include "stages/geometry/edge_polygon.h"
#include "stages/merge/area_assignment.h"
#include "stages/merge/area_graph_geometry.h"
#include "stages/merge/bay_folding.h"
#include "stages/merge/corridor_joining.h"
#include "stages/merge/room_joining.h"

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

// The areas that share a graph vertex with each area.
std::vector<std::set<int>> GraphNeighbours(const proto::CutGraph& graph, const AreaPlan& plan) {
  std::vector<std::set<int>> areas_at(graph.vertices_size());
  for (int e = 0; e < graph.edges_size(); ++e) {
    areas_at[graph.edges(e).source()].insert(plan.area_of_edge[e]);
    areas_at[graph.edges(e).target()].insert(plan.area_of_edge[e]);
  }
  std::vector<std::set<int>> neighbours(plan.areas.size());
  for (const std::set<int>& at : areas_at) {
    for (int a : at) {
      for (int b : at) {
        if (a != b) neighbours[a].insert(b);
      }
    }
  }
  return neighbours;
}

// Folds areas with fewer than `min_cells` cells into a neighbour: one that
// shares a vertex and a border, else the one with the longest border, else
// (no cells at all) the biggest that shares a vertex.
void FoldSmallAreas(const proto::CutGraph& graph, int64_t min_cells, AreaPlan* plan,
                    AreaRaster* raster) {
  std::set<int> unfoldable;
  std::vector<cv::Rect> box = AreaBoxes(*raster);
  for (;;) {
    int smallest = -1;
    for (size_t k = 0; k < plan->areas.size(); ++k) {
      if (raster->cell_count[k] >= min_cells || unfoldable.count(static_cast<int>(k))) continue;
      if (smallest < 0 || raster->cell_count[k] < raster->cell_count[smallest]) {
        smallest = static_cast<int>(k);
      }
    }
    if (smallest < 0 || plan->areas.size() < 2) return;
    const std::vector<std::set<int>> neighbours = GraphNeighbours(graph, *plan);
    const int64_t count = static_cast<int64_t>(plan->areas.size());
    const std::vector<int64_t> border = BordersOf(*raster, smallest, box[smallest]);
    auto pick = [&](auto score, bool graph_only) {
      int best = -1;
      for (int k = 0; k < count; ++k) {
        if (k == smallest || (graph_only && !neighbours[smallest].count(k))) continue;
        if (score(k) <= 0) continue;
        if (best < 0 || score(k) > score(best)) best = k;
      }
      return best;
    };
    auto by_border = [&](int k) { return border[k]; };
    auto by_size = [&](int k) { return raster->cell_count[k] + 1; };
    int into = pick(by_border, true);
    if (into < 0) into = pick(by_border, false);
    if (into < 0 && raster->cell_count[smallest] == 0) into = pick(by_size, true);
    if (into < 0) {
      unfoldable.insert(smallest);
      continue;
    }
    plan->MergeInto(smallest, into);
    MergeAreaCells(smallest, into, raster);
    if (box[smallest].area() > 0) {
      box[into] = box[into].area() == 0 ? box[smallest] : (box[into] | box[smallest]);
    }
    box.erase(box.begin() + smallest);
    // Indices above `smallest` shifted down.
    std::set<int> shifted;
    for (int k : unfoldable) shifted.insert(k > smallest ? k - 1 : k);
    unfoldable = std::move(shifted);
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

}  // namespace

proto::AreaGraph BuildAreaGraph(const proto::CutGraph& graph, const proto::CleanedMap& map,
                                const proto::MergeOptions& options, AreaRaster* raster_out) {
  CheckMergeOptions(options);
  const CellGrid grid(map);
  CheckCutGraph(graph);
  const double cell_m2 = grid.resolution_m() * grid.resolution_m();

  AreaPlan plan = AssignAreas(graph);
  if (options.join_corridor_pieces()) JoinCorridorPieces(graph, &plan);
  if (options.join_rooms_without_doors()) JoinRoomsWithoutDoors(graph, grid.resolution_m(), &plan);
  if (options.fold_open_bays()) FoldOpenBays(graph, &plan);
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
  cv::Mat removed;
  if (!options.cover_removed_obstacles()) {
    removed = cv::Mat::zeros(grid.height(), grid.width(), CV_8U);
    for (const auto* list : {&map.removed_outlier_cells(), &map.removed_furniture_cells()}) {
      for (const int index : *list) {
        if (index >= 0 && index < grid.width() * grid.height()) removed.data[index] = 1;
      }
    }
  }
  AreaRaster raster =
      PartitionFreeSpace(grid, graph.boundary(), polygons, paths, ThroughPaths(graph, plan),
                         options.grow_min_gap_m() / grid.resolution_m(), removed);
  const int64_t min_cells =
      std::max<int64_t>(1, static_cast<int64_t>(std::ceil(options.min_area_m2() / cell_m2)));
  FoldSmallAreas(graph, min_cells, &plan, &raster);
  if (std::all_of(raster.cell_count.begin(), raster.cell_count.end(),
                  [](int64_t n) { return n == 0; })) {
    throw InputError("no Area Graph: no free cell lies inside the map's boundary");
  }

  proto::AreaGraph out;
  out.set_format_version(kAreaGraphFormatVersion);
  *out.mutable_frame() = map.frame();
  AddAreasAndPassages(graph, plan, raster, options, &out);
  if (raster_out != nullptr) *raster_out = std::move(raster);
  return out;
}

}  // namespace areagraph
