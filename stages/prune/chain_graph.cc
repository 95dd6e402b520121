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

namespace {

// The maximal paths of JoinDegreeTwoChains over edges (source[e], target[e]):
// each path's edge ends in walking order (at_target: the edge is walked
// backwards), the paths in `starts`. Sets forced_junction on one vertex of
// each pure cycle. Edge ends at a vertex are in edge order (source end
// first), as Incidences gives them.
struct DegreeTwoWalks {
  std::vector<Incidence> steps;
  std::vector<int> starts;
};

DegreeTwoWalks WalkDegreeTwo(const std::vector<int>& source, const std::vector<int>& target,
                             std::vector<ChainVertex>& vertices) {
  const int vertex_count = static_cast<int>(vertices.size());
  const int edge_count = static_cast<int>(source.size());
  // Incidences in one array, by vertex (offsets), in edge order.
  std::vector<int> offset(vertex_count + 1, 0);
  for (int e = 0; e < edge_count; ++e) ++offset[source[e] + 1], ++offset[target[e] + 1];
  for (int v = 0; v < vertex_count; ++v) offset[v + 1] += offset[v];
  std::vector<Incidence> at(offset.back());
  std::vector<int> fill(offset.begin(), offset.end() - 1);
  for (int e = 0; e < edge_count; ++e) {
    at[fill[source[e]]++] = {e, false};
    at[fill[target[e]]++] = {e, true};
  }
  auto is_anchor = [&](int v) {
    // A vertex whose two ends belong to one edge carries a loop: keep it.
    return offset[v + 1] - offset[v] != 2 || vertices[v].forced_junction ||
           at[offset[v]].edge == at[offset[v] + 1].edge;
  };

  DegreeTwoWalks walks;
  walks.steps.reserve(edge_count);
  std::vector<char> used(edge_count, 0);
  auto walk = [&](int start, Incidence first) {
    walks.starts.push_back(static_cast<int>(walks.steps.size()));
    Incidence end = first;
    for (;;) {
      used[end.edge] = 1;
      walks.steps.push_back(end);
      const int v = end.at_target ? source[end.edge] : target[end.edge];
      if (v == start || is_anchor(v)) break;
      const Incidence next = at[offset[v]].edge == end.edge ? at[offset[v] + 1] : at[offset[v]];
      if (used[next.edge]) break;
      end = next;
    }
  };
  for (int v = 0; v < vertex_count; ++v) {
    if (offset[v] == offset[v + 1] || !is_anchor(v)) continue;
    for (int k = offset[v]; k < offset[v + 1]; ++k) {
      if (!used[at[k].edge]) walk(v, at[k]);
    }
  }
  // What is left are pure cycles through vertices of degree 2.
  for (int e = 0; e < edge_count; ++e) {
    if (used[e]) continue;
    vertices[source[e]].forced_junction = true;
    walk(source[e], Incidence{e, false});
  }
  walks.starts.push_back(static_cast<int>(walks.steps.size()));
  return walks;
}

}  // namespace

void ChainGraph::JoinDegreeTwoChains() {
  CompactEdges();
  std::vector<int> source(edges.size()), target(edges.size());
  for (size_t e = 0; e < edges.size(); ++e)
    source[e] = edges[e].source, target[e] = edges[e].target;
  const DegreeTwoWalks walks = WalkDegreeTwo(source, target, vertices);
  // Each edge enters one chain and `edges` is replaced at the end, so the
  // chains turn and move the edges themselves instead of copying them.
  auto take = [&](const Incidence& end) -> ChainEdge& {
    if (end.at_target) edges[end.edge].Reverse();
    return edges[end.edge];
  };
  std::vector<ChainEdge> joined;
  joined.reserve(walks.starts.size() - 1);
  for (size_t w = 0; w + 1 < walks.starts.size(); ++w) {
    ChainEdge chain = std::move(take(walks.steps[walks.starts[w]]));
    for (int k = walks.starts[w] + 1; k < walks.starts[w + 1]; ++k) {
      chain.Append(std::move(take(walks.steps[k])));
    }
    joined.push_back(std::move(chain));
  }
  edges = std::move(joined);
}

void ChainGraph::JoinSegments(const std::vector<ChainSegment>& segments, const PointList& sites) {
  std::vector<int> source(segments.size()), target(segments.size());
  for (size_t e = 0; e < segments.size(); ++e) {
    source[e] = segments[e].source, target[e] = segments[e].target;
  }
  const DegreeTwoWalks walks = WalkDegreeTwo(source, target, vertices);
  edges.clear();
  edges.reserve(walks.starts.size() - 1);
  for (size_t w = 0; w + 1 < walks.starts.size(); ++w) {
    const int first = walks.starts[w], end = walks.starts[w + 1];
    const size_t length = static_cast<size_t>(end - first);
    ChainEdge chain;
    chain.path.reserve(length + 1);
    chain.clearance_px.reserve(length + 1);
    chain.left_sites.reserve(length);
    chain.right_sites.reserve(length);
    for (int k = first; k < end; ++k) {
      const ChainSegment& segment = segments[walks.steps[k].edge];
      // Walked backwards, the segment's sides swap (ChainEdge::Reverse).
      const bool back = walks.steps[k].at_target;
      const int from = back ? segment.target : segment.source;
      const int to = back ? segment.source : segment.target;
      if (k == first) {
        chain.source = from;
        chain.path.push_back(vertices[from].position);
        chain.clearance_px.push_back(vertices[from].clearance_px);
        chain.min_clearance_px = segment.clearance_px;
      } else {
        chain.min_clearance_px = std::min(chain.min_clearance_px, segment.clearance_px);
      }
      chain.path.push_back(vertices[to].position);
      chain.clearance_px.push_back(vertices[to].clearance_px);
      chain.left_sites.push_back(sites[back ? segment.right_site : segment.left_site]);
      chain.right_sites.push_back(sites[back ? segment.left_site : segment.right_site]);
      chain.target = to;
    }
    edges.push_back(std::move(chain));
  }
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
