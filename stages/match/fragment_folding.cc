#include "stages/match/fragment_folding.h"

#include <algorithm>
#include <map>

#include "stages/match/graph_assembly.h"
#include "stages/match/polygon_union.h"

namespace areagraph {

std::vector<AreaFold> FindNoiseFragments(const proto::AreaGraph& current,
                                         const proto::AreaGraph& previous,
                                         const std::vector<int>& ids, const AreaCells& cells,
                                         const std::vector<AreaOverlap>& overlaps, double max_m2) {
  // The previous area holding most of each current area's cells.
  std::vector<int> best(current.areas_size(), -1);
  std::vector<int64_t> best_cells(current.areas_size(), 0);
  for (const AreaOverlap& pair : overlaps) {
    if (pair.cells > best_cells[pair.after]) {
      best[pair.after] = pair.before;
      best_cells[pair.after] = pair.cells;
    }
  }
  std::map<int, int> area_of_id;  // stable id -> index in current
  for (int i = 0; i < current.areas_size(); ++i) {
    if (ids[i] >= 0) area_of_id[ids[i]] = i;
  }
  std::vector<AreaFold> folds;
  for (int i = 0; i < current.areas_size(); ++i) {
    if (ids[i] >= 0 || best[i] < 0) continue;
    if (best_cells[i] < kFragmentInsideShare * cells.cells[i]) continue;
    const auto parent = area_of_id.find(previous.areas(best[i]).stable_id());
    if (parent == area_of_id.end()) continue;
    if (current.areas(i).area_m2() >= max_m2) continue;
    proto::Polygon joined;
    if (!UnionOfNeighbours(current.areas(parent->second).polygon_m(), current.areas(i).polygon_m(),
                           &joined)) {
      continue;  // they do not share a border
    }
    folds.push_back({i, parent->second});
  }
  return folds;
}

proto::AreaGraph FoldAreas(const proto::AreaGraph& graph, const std::vector<AreaFold>& folds,
                           int* folded) {
  std::vector<proto::Area> areas(graph.areas().begin(), graph.areas().end());
  std::vector<int> owner(areas.size());  // the area each one now belongs to
  for (size_t i = 0; i < owner.size(); ++i) owner[i] = static_cast<int>(i);
  int done = 0;
  for (const AreaFold& fold : folds) {
    const int into = owner[fold.into];
    if (owner[fold.fragment] != fold.fragment || into == fold.fragment) continue;
    proto::Area& target = areas[into];
    const proto::Area& piece = areas[fold.fragment];
    proto::Polygon polygon_px, polygon_m;
    if (!UnionOfNeighbours(target.polygon_px(), piece.polygon_px(), &polygon_px) ||
        !UnionOfNeighbours(target.polygon_m(), piece.polygon_m(), &polygon_m)) {
      continue;
    }
    *target.mutable_polygon_px() = std::move(polygon_px);
    *target.mutable_polygon_m() = std::move(polygon_m);
    const double total = target.area_m2() + piece.area_m2();
    if (total > 0) {
      const double wt = target.area_m2() / total, wp = piece.area_m2() / total;
      proto::Point2* centroid = target.mutable_centroid_m();
      centroid->set_x(wt * centroid->x() + wp * piece.centroid_m().x());
      centroid->set_y(wt * centroid->y() + wp * piece.centroid_m().y());
    }
    target.set_area_m2(total);
    target.mutable_topology_edge_ids()->MergeFrom(piece.topology_edge_ids());
    std::sort(target.mutable_topology_edge_ids()->begin(),
              target.mutable_topology_edge_ids()->end());
    for (int& o : owner) {
      if (o == fold.fragment) o = into;
    }
    ++done;
  }
  if (folded != nullptr) *folded = done;

  std::vector<int> index(areas.size(), -1);  // old index -> new index
  std::vector<proto::Area> kept_areas;
  for (size_t i = 0; i < areas.size(); ++i) {
    if (owner[i] != static_cast<int>(i)) continue;
    index[i] = static_cast<int>(kept_areas.size());
    kept_areas.push_back(std::move(areas[i]));
  }
  std::vector<proto::Passage> passages;
  for (const proto::Passage& passage : graph.passages()) {
    const int a = index[owner[passage.area_a()]], b = index[owner[passage.area_b()]];
    if (a == b) continue;  // the border it opened is inside one area now
    passages.push_back(passage);
    passages.back().set_area_a(a);
    passages.back().set_area_b(b);
  }
  return AssembleGraph(graph, std::move(kept_areas), std::move(passages));
}

}  // namespace areagraph
