#include "stages/prune/chain_pruning.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numeric>
#include <utility>

#include "stages/geometry/parallel_ranges.h"

namespace areagraph {
namespace {

constexpr double kTwoPi = 2 * M_PI;

// Angle from `from` to `to`, turning clockwise on screen, in (0, 2 pi].
double ClockwiseTurn(double from, double to) {
  double turn = std::fmod(to - from, kTwoPi);
  if (turn <= 0) turn += kTwoPi;
  return turn;
}

std::vector<int> Degrees(const std::vector<std::vector<Incidence>>& incidences) {
  std::vector<int> degree(incidences.size());
  for (size_t v = 0; v < incidences.size(); ++v) degree[v] = static_cast<int>(incidences[v].size());
  return degree;
}

std::vector<int> EdgesByLength(const ChainGraph& graph) {
  std::vector<int> order(graph.edges.size());
  std::iota(order.begin(), order.end(), 0);
  // The lengths over ranges of the chains in parallel (each its own).
  std::vector<double> length(graph.edges.size());
  ForEachRange(graph.edges.size(), ParallelRangeCount(graph.edges.size(), 256),
               [&](size_t begin, size_t end, int) {
                 for (size_t e = begin; e < end; ++e) length[e] = graph.edges[e].Length();
               });
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return length[a] < length[b]; });
  return order;
}

// Whether all `sites` (obstacle cell centres) are the first one's cell or
// cells touching it (8-neighbours).
bool WithinNeighbours(const PointList& sites) {
  for (const Eigen::Vector2d& site : sites) {
    const Eigen::Vector2d step = (site - sites.front()).cwiseAbs();
    if (step.x() > 1 || step.y() > 1) return false;
  }
  return !sites.empty();
}

}  // namespace

bool IsCornerSpur(const ChainEdge& edge) {
  return WithinNeighbours(edge.left_sites) || WithinNeighbours(edge.right_sites);
}

int RemoveShortDeadEnds(ChainGraph* graph, double max_length_px) {
  std::vector<std::vector<Incidence>> incidences = graph->Incidences();
  std::vector<int> degree = Degrees(incidences);
  auto is_dead_end = [&](const ChainEdge& edge) {
    return edge.source != edge.target && (degree[edge.source] == 1 || degree[edge.target] == 1);
  };

  int removed = 0;
  for (int e : EdgesByLength(*graph)) {
    ChainEdge& edge = graph->edges[e];
    if (edge.removed || !is_dead_end(edge)) continue;
    if (edge.Length() >= max_length_px && !IsCornerSpur(edge)) continue;
    // Both ends free: the last edge of its group stays.
    if (degree[edge.source] == 1 && degree[edge.target] == 1) continue;
    const bool junction_is_target = degree[edge.source] == 1;
    const int junction = junction_is_target ? edge.target : edge.source;
    const double own_angle = LeavingAngle(edge, junction_is_target);

    int next = -1, last = -1;
    double next_turn = 0, last_turn = 0;
    for (const Incidence& other : incidences[junction]) {
      if (other.edge == e || graph->edges[other.edge].removed) continue;
      const double turn =
          ClockwiseTurn(own_angle, LeavingAngle(graph->edges[other.edge], other.at_target));
      if (next < 0 || turn < next_turn) next = other.edge, next_turn = turn;
      if (last < 0 || turn > last_turn) last = other.edge, last_turn = turn;
    }
    if (next < 0) continue;
    const int recipient = is_dead_end(graph->edges[next]) ? last : next;

    std::vector<proto::Polygon> polygons = edge.TakeAllPolygons();
    auto& absorbed = graph->edges[recipient].absorbed;
    absorbed.insert(absorbed.end(), std::make_move_iterator(polygons.begin()),
                    std::make_move_iterator(polygons.end()));
    edge.removed = true;
    --degree[edge.source];
    --degree[edge.target];
    ++removed;
  }
  return removed;
}

int MergeCloseJunctions(ChainGraph* graph) {
  int merged_total = 0;
  for (;;) {
    const std::vector<std::vector<Incidence>> incidences = graph->Incidences();
    const std::vector<int> degree = Degrees(incidences);
    std::vector<bool> touched(graph->vertices.size(), false);
    int merged = 0;
    for (int e : EdgesByLength(*graph)) {
      ChainEdge& edge = graph->edges[e];
      if (edge.removed || edge.source == edge.target) continue;
      if (degree[edge.source] < 3 || degree[edge.target] < 3) continue;
      if (touched[edge.source] || touched[edge.target]) continue;
      const ChainVertex& a = graph->vertices[edge.source];
      const ChainVertex& b = graph->vertices[edge.target];
      if (edge.Length() >= std::min(a.clearance_px, b.clearance_px)) continue;

      const int keep = a.clearance_px >= b.clearance_px ? edge.source : edge.target;
      const int gone = keep == edge.source ? edge.target : edge.source;
      int recipient = -1;
      for (const Incidence& other : incidences[keep]) {
        if (other.edge == e || graph->edges[other.edge].removed) continue;
        if (recipient < 0 || graph->edges[other.edge].Length() > graph->edges[recipient].Length()) {
          recipient = other.edge;
        }
      }
      if (recipient < 0) continue;
      // Its own faces go with the extended edges below; what it absorbed
      // goes to the longest other edge at the kept junction.
      auto& absorbed = graph->edges[recipient].absorbed;
      // Moved: the edge is removed below.
      absorbed.insert(absorbed.end(), std::make_move_iterator(edge.absorbed.begin()),
                      std::make_move_iterator(edge.absorbed.end()));
      edge.absorbed.clear();
      // The other edges of the dropped junction now start at the kept one,
      // along the merged edge: their paths stay Voronoi chains, so their
      // polygons stay valid (they overlap on the merged edge's faces).
      ChainEdge bridge = edge.source == keep ? edge : edge.Reversed();
      bridge.absorbed.clear();
      // Turned in place and moved rather than copied: an edge's absorbed
      // polygons are not copied twice and then dropped.
      for (const Incidence& moved : incidences[gone]) {
        ChainEdge& other = graph->edges[moved.edge];
        if (moved.edge == e || other.removed) continue;
        ChainEdge extended = bridge;
        if (moved.at_target) other.Reverse();
        extended.Append(std::move(other));
        if (moved.at_target) extended.Reverse();
        other = std::move(extended);
      }
      edge.removed = true;
      touched[keep] = touched[gone] = true;
      ++merged;
    }
    merged_total += merged;
    if (merged == 0) break;
    graph->CompactEdges();
  }
  return merged_total;
}

}  // namespace areagraph
