#include "stages/merge/split_corridor_joining.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "stages/geometry/corridor_shape.h"
#include "stages/geometry/disjoint_sets.h"
#include "stages/geometry/edge_polygon.h"
#include "stages/merge/area_shapes.h"
#include "stages/merge/one_sided_narrowing.h"
#include "stages/merge/plan_model.h"
#include "stages/merge/vertex_openings.h"

namespace areagraph {
void JoinSplitCorridors(const proto::CutGraph& graph, double resolution_m, double robot_width_m,
                        const std::vector<bool>& closed, AreaPlan* plan,
                        const SplitCorridorParams& params, const CellGrid* grid) {
  const double bend_cos = std::cos(params.bend_deg * M_PI / 180);
  for (int pass = 0; pass < 8; ++pass) {
    const int area_count = static_cast<int>(plan->areas.size());
    const PlanModel model = MeasurePlan(graph, *plan, resolution_m);
    const std::vector<AreaShape>& shapes = model.shapes;
    // The two (or a chain of) areas as one: shaped like a corridor?
    const auto corridor = [&](double typical, double widest, double area_px) {
      return IsCorridorShaped(typical, widest, area_px, resolution_m);
    };
    // Pairs that pass every test; `long_enough`: the pair alone is shaped
    // like a corridor.
    struct Pair {
      int i, j;
      bool long_enough;
    };
    std::vector<Pair> pairs;
    for (int vertex = 0; vertex < graph.vertices_size(); ++vertex) {
      if (closed[vertex]) continue;
      const std::map<int, VertexOpening>& at = model.openings[vertex];
      for (auto a = at.begin(); a != at.end(); ++a) {
        for (auto b = std::next(a); b != at.end(); ++b) {
          const int i = a->first, j = b->first;
          const double narrow = std::min(shapes[i].typical_px, shapes[j].typical_px);
          const double wide = std::max(shapes[i].typical_px, shapes[j].typical_px);
          if (narrow <= 0 || wide > kCorridorWidthRatio * narrow) continue;
          if (narrow < 2 * robot_width_m / resolution_m) continue;
          const VertexOpening& narrowest =
              a->second.width_px <= b->second.width_px ? a->second : b->second;
          const double opening = narrowest.width_px;
          if (NarrowsCorridor(opening, wide)) {
            if (grid == nullptr || !OneSidedNarrowing(*grid, narrowest.left, narrowest.right)) {
              continue;
            }
          }
          const bool long_enough =
              corridor(wide, std::max(shapes[i].widest_px, shapes[j].widest_px),
                       shapes[i].area_px + shapes[j].area_px);
          const AreaMoments& mi = shapes[i].moments;
          const AreaMoments& mj = shapes[j].moments;
          if (mi.a <= 0 || mj.a <= 0) continue;
          const Eigen::Vector2d vertex_at = FromProtoPoint(graph.vertices(vertex).position());
          const Eigen::Vector2d ci = mi.Centroid(), cj = mj.Centroid();
          const double across = (ci - vertex_at).normalized().dot((cj - vertex_at).normalized());
          if (across > -bend_cos) continue;
          pairs.push_back({i, j, long_enough});
        }
      }
    }
    // A pair too short alone joins when the chain of pairs it belongs to is
    // shaped like a corridor.
    std::vector<bool> chain_long(area_count, false);
    DisjointSets chains(area_count);
    for (const Pair& pair : pairs) chains.Union(pair.i, pair.j);
    std::vector<double> chain_px(area_count, 0), chain_typical(area_count, 0),
        chain_widest(area_count, 0);
    for (int k = 0; k < area_count; ++k) {
      const int root = chains.Find(k);
      chain_px[root] += shapes[k].area_px;
      chain_typical[root] = std::max(chain_typical[root], shapes[k].typical_px);
      chain_widest[root] = std::max(chain_widest[root], shapes[k].widest_px);
    }
    for (int k = 0; k < area_count; ++k) {
      const int root = chains.Find(k);
      chain_long[k] = corridor(chain_typical[root], chain_widest[root], chain_px[root]);
    }
    DisjointSets groups(area_count);
    bool changed = false;
    for (const Pair& pair : pairs) {
      if (!pair.long_enough && !chain_long[pair.i]) continue;
      if (groups.Union(pair.i, pair.j)) changed = true;
    }
    if (!changed) break;
    std::vector<int> root(area_count);
    for (int k = 0; k < area_count; ++k) root[k] = groups.Find(k);
    plan->MergeGroups(root);
  }
}

}  // namespace areagraph
