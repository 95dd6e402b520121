#include "stages/prune/chain_graph.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <utility>

#include "stages/geometry/disjoint_sets.h"

namespace areagraph {
namespace {

template <typename T>
void AppendTail(const std::vector<T>& tail, size_t skip, std::vector<T>* out) {
  out->insert(out->end(), tail.begin() + std::min(skip, tail.size()), tail.end());
}

}  // namespace

ChainEdge ChainEdge::Reversed() const {
  ChainEdge reversed = *this;
  reversed.Reverse();
  return reversed;
}

void ChainEdge::Reverse() {
  std::swap(source, target);
  std::reverse(path.begin(), path.end());
  std::reverse(clearance_px.begin(), clearance_px.end());
  // Walking the other way swaps the sides.
  std::swap(left_sites, right_sites);
  std::reverse(left_sites.begin(), left_sites.end());
  std::reverse(right_sites.begin(), right_sites.end());
}

void ChainEdge::Append(const ChainEdge& next) {
  AppendTail(next.path, 1, &path);
  AppendTail(next.clearance_px, 1, &clearance_px);
  AppendTail(next.left_sites, 0, &left_sites);
  AppendTail(next.right_sites, 0, &right_sites);
  AppendTail(next.absorbed, 0, &absorbed);
  min_clearance_px = std::min(min_clearance_px, next.min_clearance_px);
  target = next.target;
}

void ChainEdge::Append(ChainEdge&& next) {
  std::vector<proto::Polygon> moved = std::move(next.absorbed);
  next.absorbed.clear();
  Append(next);
  absorbed.insert(absorbed.end(), std::make_move_iterator(moved.begin()),
                  std::make_move_iterator(moved.end()));
}

std::vector<proto::Polygon> ChainEdge::TakeAllPolygons() {
  std::vector<proto::Polygon> polygons;
  polygons.reserve(1 + absorbed.size());
  proto::Polygon own;
  *own.mutable_outer() = EdgePolygonRing(path, left_sites, right_sites);
  polygons.push_back(std::move(own));
  polygons.insert(polygons.end(), std::make_move_iterator(absorbed.begin()),
                  std::make_move_iterator(absorbed.end()));
  absorbed.clear();
  return polygons;
}

double LeavingAngle(const ChainEdge& edge, bool at_target) {
  const int n = static_cast<int>(edge.path.size());
  const Eigen::Vector2d& from = at_target ? edge.path[n - 1] : edge.path[0];
  // Skip zero-length segments, which degenerate grid diagrams contain.
  for (int k = 1; k < n; ++k) {
    const Eigen::Vector2d& to = at_target ? edge.path[n - 1 - k] : edge.path[k];
    const Eigen::Vector2d d = to - from;
    if (d.squaredNorm() > 1e-12) return std::atan2(d.y(), d.x());
  }
  return 0;
}

std::vector<std::vector<Incidence>> ChainGraph::Incidences() const {
  std::vector<std::vector<Incidence>> incidences(vertices.size());
  for (size_t e = 0; e < edges.size(); ++e) {
    if (edges[e].removed) continue;
    incidences[edges[e].source].push_back({static_cast<int>(e), false});
    incidences[edges[e].target].push_back({static_cast<int>(e), true});
  }
  return incidences;
}

void ChainGraph::CompactEdges() {
  edges.erase(
      std::remove_if(edges.begin(), edges.end(), [](const ChainEdge& e) { return e.removed; }),
      edges.end());
}

void ChainGraph::JoinDegreeTwoChains() {
  CompactEdges();
  const std::vector<std::vector<Incidence>> incidences = Incidences();
  auto is_anchor = [&](int v) {
    const auto& at = incidences[v];
    // A vertex whose two ends belong to one edge carries a loop: keep it.
    return at.size() != 2 || vertices[v].forced_junction || at[0].edge == at[1].edge;
  };

  std::vector<bool> used(edges.size(), false);
  std::vector<ChainEdge> joined;
  // Each edge enters one chain and `edges` is replaced at the end, so the
  // walk turns and moves the edges themselves instead of copying them.
  auto take = [&](const Incidence& end) -> ChainEdge& {
    used[end.edge] = true;
    if (end.at_target) edges[end.edge].Reverse();
    return edges[end.edge];
  };
  auto walk = [&](int start, Incidence first) {
    ChainEdge chain = std::move(take(first));
    int came_by = first.edge;
    int v = chain.target;
    while (v != start && !is_anchor(v)) {
      const auto& at = incidences[v];
      const Incidence next = at[0].edge == came_by ? at[1] : at[0];
      if (used[next.edge]) break;
      chain.Append(std::move(take(next)));
      came_by = next.edge;
      v = chain.target;
    }
    joined.push_back(std::move(chain));
  };

  for (size_t v = 0; v < vertices.size(); ++v) {
    if (incidences[v].empty() || !is_anchor(static_cast<int>(v))) continue;
    for (const Incidence& incidence : incidences[v]) {
      if (!used[incidence.edge]) walk(static_cast<int>(v), incidence);
    }
  }
  // What is left are pure cycles through vertices of degree 2.
  for (size_t e = 0; e < edges.size(); ++e) {
    if (used[e]) continue;
    const int start = edges[e].source;
    vertices[start].forced_junction = true;
    walk(start, Incidence{static_cast<int>(e), false});
  }
  edges = std::move(joined);
}

PartSelection ChainGraph::KeepParts(const std::function<int(int vertex)>& part_of,
                                    const std::vector<int64_t>& part_cells, int64_t min_cells,
                                    double min_group_length_px) {
  PartSelection selection;
  if (vertices.empty()) return selection;
  DisjointSets groups(vertices.size());
  for (const ChainEdge& edge : edges) {
    if (!edge.removed) groups.Union(edge.source, edge.target);
  }
  std::vector<double> group_length(vertices.size(), 0.0);
  for (const ChainEdge& edge : edges) {
    if (!edge.removed) group_length[groups.Find(edge.source)] += edge.Length();
  }
  // The part of each group: where most of its vertices are.
  std::vector<std::map<int, int>> votes(vertices.size());
  for (size_t v = 0; v < vertices.size(); ++v) {
    const int group = groups.Find(static_cast<int>(v));
    if (group_length[group] > 0) ++votes[group][part_of(static_cast<int>(v))];
  }
  std::vector<int> group_part(vertices.size(), -1);
  for (size_t group = 0; group < vertices.size(); ++group) {
    int most = 0;
    for (const auto& [part, count] : votes[group]) {
      if (count > most) most = count, group_part[group] = part;
    }
  }
  const int biggest = static_cast<int>(std::max_element(group_length.begin(), group_length.end()) -
                                       group_length.begin());
  // Per part, its longest group (the biggest group wins its own part).
  std::map<int, int> longest_in_part;
  for (size_t group = 0; group < vertices.size(); ++group) {
    if (group_length[group] <= 0) continue;
    auto [it, added] = longest_in_part.emplace(group_part[group], static_cast<int>(group));
    if (!added && group_length[group] > group_length[it->second])
      it->second = static_cast<int>(group);
  }
  longest_in_part[group_part[biggest]] = biggest;
  std::vector<char> keep(vertices.size(), 0);
  for (const auto& [part, group] : longest_in_part) {
    const bool big_enough = part >= 0 && part_cells[part] >= min_cells;
    if (group == biggest || big_enough) {
      keep[group] = 1;
      ++selection.kept;
    } else if (part >= 0) {
      ++selection.dropped;
      selection.dropped_cells += part_cells[part];
    }
  }
  // A long group beside a longer one in its part: a room behind a gap the
  // graph does not pass, which the areas' growth does not pass either.
  if (min_group_length_px > 0) {
    for (size_t group = 0; group < vertices.size(); ++group) {
      if (keep[group] || group_length[group] < min_group_length_px) continue;
      if (group_part[group] < 0 || part_cells[group_part[group]] < min_cells) continue;
      keep[group] = 1;
      ++selection.kept;
    }
  }
  for (ChainEdge& edge : edges) {
    if (!edge.removed && !keep[groups.Find(edge.source)]) edge.removed = true;
  }
  CompactEdges();
  return selection;
}

}  // namespace areagraph
