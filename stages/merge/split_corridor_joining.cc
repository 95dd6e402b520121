#include "stages/merge/split_corridor_joining.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "stages/geometry/disjoint_sets.h"
#include "stages/geometry/edge_polygon.h"
#include "stages/merge/area_moments.h"
#include "stages/merge/corridor_labels.h"
#include "stages/merge/one_sided_narrowing.h"
#include "stages/merge/vertex_openings.h"

namespace areagraph {
void JoinSplitCorridors(const proto::CutGraph& graph, double resolution_m, bool keep_closed_doors,
                        AreaPlan* plan, const SplitCorridorParams& params, const CellGrid* grid) {
  const std::vector<bool> closed = ClosedVertices(graph, keep_closed_doors);
  const double max_width_px = kMaxCorridorWidthM / resolution_m;
  const double cell_m2 = resolution_m * resolution_m;
  const double straight_cos = std::cos(params.straight_deg * M_PI / 180);
  const double axis_cos = std::cos(params.axis_deg * M_PI / 180);
  for (int pass = 0; pass < 8; ++pass) {
    const int area_count = static_cast<int>(plan->areas.size());
    const std::vector<double> size_m2 = AreaSizesM2(graph, *plan, resolution_m);
    std::vector<double> width(area_count);
    for (int k = 0; k < area_count; ++k) width[k] = MedianWidthPx(graph, plan->areas[k]);
    const std::vector<std::map<int, VertexOpening>> openings = OpeningsAtVertices(graph, *plan);
    const std::vector<AreaMoments> moments = MomentsOfAreas(graph, *plan);
    // Pairs that pass every test; `long_enough`: the pair alone covers the
    // elongation's squares.
    struct Pair {
      int i, j;
      bool long_enough;
    };
    std::vector<Pair> pairs;
    for (int vertex = 0; vertex < graph.vertices_size(); ++vertex) {
      if (closed[vertex]) continue;
      const std::map<int, VertexOpening>& at = openings[vertex];
      for (auto a = at.begin(); a != at.end(); ++a) {
        for (auto b = std::next(a); b != at.end(); ++b) {
          const int i = a->first, j = b->first;
          const double narrow = std::min(width[i], width[j]);
          const double wide = std::max(width[i], width[j]);
          if (narrow <= 0 || wide > max_width_px || wide > params.width_ratio * narrow) continue;
          if (narrow < params.min_width_m / resolution_m) continue;
          const VertexOpening& narrowest =
              a->second.width_px <= b->second.width_px ? a->second : b->second;
          const double opening = narrowest.width_px;
          if (opening < params.opening_share * wide) {
            if (grid == nullptr || opening < params.one_sided_opening_share * wide ||
                !OneSidedNarrowing(*grid, narrowest.left, narrowest.right)) {
              continue;
            }
          }
          const double union_px = (size_m2[i] + size_m2[j]) / cell_m2;
          const bool long_enough = union_px >= params.elongation * wide * wide;
          if (!long_enough && !params.chains) continue;
          if (moments[i].a <= 0 || moments[j].a <= 0) continue;
          const Eigen::Vector2d vertex_at = FromProtoPoint(graph.vertices(vertex).position());
          const Eigen::Vector2d ci = moments[i].Centroid(), cj = moments[j].Centroid();
          const double across = (ci - vertex_at).normalized().dot((cj - vertex_at).normalized());
          if (across > straight_cos) continue;
          bool aligned = true;
          const Eigen::Vector2d line = (cj - ci).normalized();
          for (const int k : {i, j}) {
            const auto [axis, ratio] = moments[k].Axis();
            if (ratio >= params.axis_ratio && std::abs(axis.dot(line)) < axis_cos) aligned = false;
          }
          if (!aligned) continue;
          pairs.push_back({i, j, long_enough});
        }
      }
    }
    // With `chains`, a pair too short alone joins when the chain of pairs it
    // belongs to covers the elongation's squares of the chain's widest piece.
    std::vector<bool> chain_long(area_count, false);
    DisjointSets chains(area_count);
    if (params.chains) {
      for (const Pair& pair : pairs) chains.Union(pair.i, pair.j);
      std::vector<double> chain_px(area_count, 0), chain_wide(area_count, 0);
      for (int k = 0; k < area_count; ++k) {
        const int root = chains.Find(k);
        chain_px[root] += size_m2[k] / cell_m2;
        chain_wide[root] = std::max(chain_wide[root], width[k]);
      }
      for (int k = 0; k < area_count; ++k) {
        const int root = chains.Find(k);
        chain_long[k] = chain_px[root] >= params.elongation * chain_wide[root] * chain_wide[root];
      }
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
