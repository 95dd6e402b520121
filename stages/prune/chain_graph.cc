#include "stages/prune/chain_graph.h"

#include <algorithm>
#include <cmath>

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
  std::swap(reversed.source, reversed.target);
  std::reverse(reversed.path.begin(), reversed.path.end());
  std::reverse(reversed.clearance_px.begin(), reversed.clearance_px.end());
  // Walking the other way swaps the sides.
  reversed.left_sites.assign(right_sites.rbegin(), right_sites.rend());
  reversed.right_sites.assign(left_sites.rbegin(), left_sites.rend());
  return reversed;
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

std::vector<proto::Polygon> ChainEdge::AllPolygons() const {
  std::vector<proto::Polygon> polygons;
  polygons.reserve(1 + absorbed.size());
  proto::Polygon own;
  *own.mutable_outer() = EdgePolygonRing(path, left_sites, right_sites);
  polygons.push_back(std::move(own));
  polygons.insert(polygons.end(), absorbed.begin(), absorbed.end());
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
  auto walk = [&](int start, Incidence first) {
    ChainEdge chain = first.at_target ? edges[first.edge].Reversed() : edges[first.edge];
    used[first.edge] = true;
    int came_by = first.edge;
    int v = chain.target;
    while (v != start && !is_anchor(v)) {
      const auto& at = incidences[v];
      const Incidence next = at[0].edge == came_by ? at[1] : at[0];
      if (used[next.edge]) break;
      used[next.edge] = true;
      chain.Append(next.at_target ? edges[next.edge].Reversed() : edges[next.edge]);
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

void ChainGraph::KeepBiggestGroup() {
  if (vertices.empty()) return;
  DisjointSets groups(vertices.size());
  for (const ChainEdge& edge : edges) {
    if (!edge.removed) groups.Union(edge.source, edge.target);
  }
  std::vector<double> group_length(vertices.size(), 0.0);
  for (const ChainEdge& edge : edges) {
    if (!edge.removed) group_length[groups.Find(edge.source)] += edge.Length();
  }
  const int biggest = static_cast<int>(std::max_element(group_length.begin(), group_length.end()) -
                                       group_length.begin());
  for (ChainEdge& edge : edges) {
    if (!edge.removed && groups.Find(edge.source) != biggest) edge.removed = true;
  }
  CompactEdges();
}

}  // namespace areagraph
