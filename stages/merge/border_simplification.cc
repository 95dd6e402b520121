// Polyline simplification of all borders at once, the way CGAL's
// Polyline_simplification_2 does it on a constrained triangulation
// (Squared_distance_cost, Stop_above_cost_threshold), without building the
// triangulation: the test it makes in the triangulation is answered by a
// grid of buckets over the points. The result is CGAL's, point for point
// (tests/stages/merge/border_simplification_test.cc keeps CGAL's version as
// the reference); CGAL's kernel supplies the exact orientation predicate and
// the squared distances, so every number is computed as CGAL computes it.
//
// Why they agree. CGAL removes a vertex v between u and w of its polyline
// when u, v, w are collinear, or else when every triangulation neighbour of
// v angularly between u and w lies strictly beyond the line uw (seen from v)
// and, if w follows u directly, uw is no constraint. The fan of triangles
// around v between its constrained edges vu and vw covers the closed
// triangle uvw exactly when those neighbours lie beyond uw, and no vertex
// lies inside a triangle or on an edge of the triangulation; so the test is:
// no vertex but u, v and w in the closed triangle uvw, and u and w not
// neighbours on a polyline. Vertices removed earlier are no longer in the
// triangulation and do not count; the cost still measures every original
// point between u and w.
#include "stages/merge/border_simplification.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <unordered_map>

#include "stages/merge/cost_heap.h"

namespace areagraph {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;

// Tie-break step per vertex (square pixels): a million vertices move costs by
// 1e-6 px^2 at most. Each vertex's cost is lowered by its number in input
// order times this, so that equal costs (common on the pixel grid) are taken
// in one fixed order.
constexpr double kTieBreakStep = 1e-12;
// Side of a bucket of the point grid (px).
constexpr double kBucketPx = 8;
// How far the bucket rows and columns searched reach beyond the triangle, so
// that rounding in finding them never misses a point (px).
constexpr double kSlackPx = 1e-3;

// Vertex numbers by point (the bits of x and y), open addressing: one
// array, no node per point.
class VertexTable {
 public:
  explicit VertexTable(size_t count) {
    size_t capacity = 16;
    while (capacity < 2 * count) capacity *= 2;
    mask_ = capacity - 1;
    slots_.assign(capacity, Slot{0, 0, -1});
  }

  // The number stored for `key`, -1 for a new key (which the caller sets).
  int& Find(const std::pair<uint64_t, uint64_t>& key) {
    // The coordinates' bits vary at the top (exponent, leading mantissa):
    // folded down and mixed.
    uint64_t h = key.first ^ (key.second >> 32 | key.second << 32);
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 32;
    for (size_t i = h;; ++i) {
      Slot& slot = slots_[i & mask_];
      if (slot.id < 0) {
        slot.x = key.first, slot.y = key.second;
        return slot.id;
      }
      if (slot.x == key.first && slot.y == key.second) return slot.id;
    }
  }

 private:
  struct Slot {
    uint64_t x, y;
    int id;
  };
  size_t mask_ = 0;
  std::vector<Slot> slots_;
};

class Simplifier {
 public:
  Simplifier(const std::vector<PointList>& chains, const std::vector<double>& tolerance_px,
             double largest)
      : chains_(chains) {
    IndexPoints(tolerance_px, largest);
    BuildBuckets();
  }

  std::vector<PointList> Run(double threshold) {
    threshold_ = threshold;
    CostHeap heap(vertices_.size());
    for (size_t n = 0; n < nodes_.size(); ++n) {
      const int v = nodes_[n].vertex;
      if (!vertices_[v].removable) continue;
      double cost;
      if (Cost(static_cast<int>(n), &cost)) heap.Set(v, cost);
    }
    // Every cost in the heap is below the threshold (Cost): each one popped
    // is taken, in the order the full costs would give.
    while (!heap.empty()) {
      const int v = heap.top();
      heap.Pop();
      const int node = vertices_[v].node;
      if (!Removable(node)) continue;
      const int u = nodes_[node].prev, w = nodes_[node].next;
      nodes_[u].next = w;
      nodes_[w].prev = u;
      bucket_points_[slot_of_vertex_[v]].vertex = -1;
      for (const int n : {u, w}) {
        const int neighbour = nodes_[n].vertex;
        if (!vertices_[neighbour].removable) continue;
        double c;
        if (Cost(n, &c)) {
          heap.Set(neighbour, c);
        } else {
          heap.Erase(neighbour);
        }
      }
    }
    std::vector<PointList> simplified(chains_.size());
    for (size_t i = 0; i < chains_.size(); ++i) {
      if (chains_[i].empty()) continue;
      for (int n = chain_begin_[i]; n >= 0; n = nodes_[n].next) {
        simplified[i].push_back(chains_[i][nodes_[n].index]);
      }
    }
    return simplified;
  }

 private:
  // One point of one chain.
  struct Node {
    int vertex = -1;
    int chain = -1;
    int index = 0;             // in its chain
    int prev = -1, next = -1;  // the chain's neighbouring nodes still kept
  };
  // One distinct point (a chain end shared by several chains is one vertex).
  struct Vertex {
    Point point;
    // Its node, for a vertex inside one chain (the only ones removable).
    int node = -1;
    int occurrences = 0;
    bool removable = false;
    // (largest tolerance / its chain's tolerance)^2, infinite for a chain
    // that keeps every point, and the tie-break taken off its cost.
    double factor = 1;
    double tie_break = 0;
  };

  void IndexPoints(const std::vector<double>& tolerance_px, double largest) {
    size_t total = 0;
    for (const PointList& chain : chains_) total += chain.size();
    nodes_.reserve(total);
    vertices_.reserve(total);
    VertexTable vertex_at(total);
    chain_begin_.assign(chains_.size(), -1);
    int64_t order = 0;
    for (size_t i = 0; i < chains_.size(); ++i) {
      const PointList& chain = chains_[i];
      const double ratio = tolerance_px[i] > 0 ? largest / tolerance_px[i] : INFINITY;
      const int first = static_cast<int>(nodes_.size());
      if (!chain.empty()) chain_begin_[i] = first;
      for (size_t j = 0; j < chain.size(); ++j) {
        std::pair<uint64_t, uint64_t> key;
        const double x = chain[j].x() + 0.0, y = chain[j].y() + 0.0;  // -0 as 0
        std::memcpy(&key.first, &x, sizeof x);
        std::memcpy(&key.second, &y, sizeof y);
        int& id = vertex_at.Find(key);
        if (id < 0) {
          id = static_cast<int>(vertices_.size());
          vertices_.emplace_back();
          vertices_.back().point = Point(chain[j].x(), chain[j].y());
        }
        Vertex& vertex = vertices_[id];
        ++vertex.occurrences;
        vertex.factor = ratio * ratio;
        vertex.tie_break = kTieBreakStep * static_cast<double>(++order);
        const int n = static_cast<int>(nodes_.size());
        vertex.node = n;
        Node node;
        node.vertex = id;
        node.chain = static_cast<int>(i);
        node.index = static_cast<int>(j);
        node.prev = j > 0 ? n - 1 : -1;
        node.next = j + 1 < chain.size() ? n + 1 : -1;
        nodes_.push_back(node);
      }
    }
    // Removable: inside one chain and nowhere else (chain ends and points
    // shared with another chain stay).
    for (const Node& node : nodes_) {
      Vertex& vertex = vertices_[node.vertex];
      vertex.removable = vertex.occurrences == 1 && node.prev >= 0 && node.next >= 0 &&
                         nodes_[node.prev].vertex != nodes_[node.next].vertex;
    }
    // Vertices at several nodes keep the list of their nodes.
    for (size_t n = 0; n < nodes_.size(); ++n) {
      const int v = nodes_[n].vertex;
      if (vertices_[v].occurrences > 1) shared_nodes_[v].push_back(static_cast<int>(n));
    }
  }

  void BuildBuckets() {
    if (vertices_.empty()) return;
    double x0 = vertices_[0].point.x(), y0 = vertices_[0].point.y(), x1 = x0, y1 = y0;
    for (const Vertex& v : vertices_) {
      x0 = std::min(x0, v.point.x()), x1 = std::max(x1, v.point.x());
      y0 = std::min(y0, v.point.y()), y1 = std::max(y1, v.point.y());
    }
    origin_x_ = x0, origin_y_ = y0;
    columns_ = static_cast<int>((x1 - x0) / kBucketPx) + 1;
    rows_ = static_cast<int>((y1 - y0) / kBucketPx) + 1;
    std::vector<int> count(static_cast<size_t>(columns_) * rows_ + 1, 0);
    std::vector<int> bucket_of(vertices_.size());
    for (size_t v = 0; v < vertices_.size(); ++v) {
      bucket_of[v] =
          BucketRow(vertices_[v].point.y()) * columns_ + BucketColumn(vertices_[v].point.x());
      ++count[bucket_of[v] + 1];
    }
    for (size_t b = 1; b < count.size(); ++b) count[b] += count[b - 1];
    bucket_start_ = count;
    bucket_points_.resize(vertices_.size());
    slot_of_vertex_.resize(vertices_.size());
    for (size_t v = 0; v < vertices_.size(); ++v) {
      const int slot = count[bucket_of[v]]++;
      bucket_points_[slot] = {vertices_[v].point.x(), vertices_[v].point.y(), static_cast<int>(v)};
      slot_of_vertex_[v] = slot;
    }
  }

  int BucketColumn(double x) const {
    return std::clamp(static_cast<int>(std::floor((x - origin_x_) / kBucketPx)), 0, columns_ - 1);
  }
  int BucketRow(double y) const {
    return std::clamp(static_cast<int>(std::floor((y - origin_y_) / kBucketPx)), 0, rows_ - 1);
  }

  // CGAL's Squared_distance_cost scaled by the vertex's factor, less its
  // tie-break; false where the vertex may never go, which includes a cost at
  // or above the threshold: the scan stops at the first point that puts it
  // there (the cost only grows with the maximum, so the answer is the same),
  // and such a vertex would never be taken anyway.
  bool Cost(int node, double* cost) const {
    const Vertex& vertex = vertices_[nodes_[node].vertex];
    if (!std::isfinite(vertex.factor)) return false;
    const int u = nodes_[node].prev, w = nodes_[node].next;
    const Kernel::Segment_2 segment(vertices_[nodes_[u].vertex].point,
                                    vertices_[nodes_[w].vertex].point);
    const PointList& chain = chains_[nodes_[node].chain];
    double d = 0.0;
    for (int j = nodes_[u].index + 1; j < nodes_[w].index; ++j) {
      const double to_point = CGAL::squared_distance(segment, Point(chain[j].x(), chain[j].y()));
      if (to_point <= d) continue;
      d = to_point;
      if (d * vertex.factor - vertex.tie_break >= threshold_) return false;
    }
    *cost = d * vertex.factor - vertex.tie_break;
    return true;
  }

  // Whether vertices a and b are neighbours on a chain (a constrained edge).
  bool Joined(int a, int b) const {
    auto joined_at = [&](int n) {
      return (nodes_[n].prev >= 0 && nodes_[nodes_[n].prev].vertex == b) ||
             (nodes_[n].next >= 0 && nodes_[nodes_[n].next].vertex == b);
    };
    if (vertices_[a].occurrences == 1) return joined_at(vertices_[a].node);
    const auto it = shared_nodes_.find(a);
    return std::any_of(it->second.begin(), it->second.end(), joined_at);
  }

  // CGAL's is_removable (see the top of the file).
  bool Removable(int node) const {
    const int u = nodes_[nodes_[node].prev].vertex, v = nodes_[node].vertex,
              w = nodes_[nodes_[node].next].vertex;
    const Point &pu = vertices_[u].point, &pv = vertices_[v].point, &pw = vertices_[w].point;
    const CGAL::Orientation turn = CGAL::orientation(pu, pv, pw);
    if (turn == CGAL::COLLINEAR) return true;
    if (AnyVertexInTriangle(pu, pv, pw, turn, u, v, w)) return false;
    return !Joined(u, w);
  }

  // Whether a vertex still there, other than a, b and c, lies in the closed triangle
  // abc (of orientation `turn`).
  bool AnyVertexInTriangle(const Point& a, const Point& b, const Point& c, CGAL::Orientation turn,
                           int ia, int ib, int ic) const {
    const double x0 = std::min({a.x(), b.x(), c.x()}), x1 = std::max({a.x(), b.x(), c.x()});
    const double y0 = std::min({a.y(), b.y(), c.y()}), y1 = std::max({a.y(), b.y(), c.y()});
    const CGAL::Orientation outside = -turn;
    const Point* corners[3] = {&a, &b, &c};
    const int r0 = BucketRow(y0), r1 = BucketRow(y1);
    for (int r = r0; r <= r1; ++r) {
      // The triangle's x-range within this row of buckets (widened by
      // kSlackPx against rounding; the exact test below decides).
      const double band0 = std::max(y0, origin_y_ + r * kBucketPx - kSlackPx);
      const double band1 = std::min(y1, origin_y_ + (r + 1) * kBucketPx + kSlackPx);
      double bx0 = x1, bx1 = x0;
      for (int e = 0; e < 3; ++e) {
        const Point& p = *corners[e];
        const Point& q = *corners[(e + 1) % 3];
        const double lo = std::max(band0, std::min(p.y(), q.y()));
        const double hi = std::min(band1, std::max(p.y(), q.y()));
        if (lo > hi) continue;
        if (p.y() == q.y()) {
          bx0 = std::min({bx0, p.x(), q.x()}), bx1 = std::max({bx1, p.x(), q.x()});
          continue;
        }
        for (const double y : {lo, hi}) {
          const double x = p.x() + (q.x() - p.x()) * ((y - p.y()) / (q.y() - p.y()));
          bx0 = std::min(bx0, x), bx1 = std::max(bx1, x);
        }
      }
      if (bx0 > bx1) continue;
      const int c0 = BucketColumn(std::max(x0, bx0 - kSlackPx)),
                c1 = BucketColumn(std::min(x1, bx1 + kSlackPx));
      for (int col = c0; col <= c1; ++col) {
        const int bucket = r * columns_ + col;
        for (int k = bucket_start_[bucket]; k < bucket_start_[bucket + 1]; ++k) {
          const BucketPoint& entry = bucket_points_[k];
          if (entry.x < x0 || entry.x > x1 || entry.y < y0 || entry.y > y1) continue;
          const int i = entry.vertex;
          if (i < 0 || i == ia || i == ib || i == ic) continue;
          const Point p(entry.x, entry.y);
          if (CGAL::orientation(a, b, p) != outside && CGAL::orientation(b, c, p) != outside &&
              CGAL::orientation(c, a, p) != outside) {
            return true;
          }
        }
      }
    }
    return false;
  }

  const std::vector<PointList>& chains_;
  double threshold_ = INFINITY;
  std::vector<Node> nodes_;
  std::vector<Vertex> vertices_;
  std::vector<int> chain_begin_;
  std::unordered_map<int, std::vector<int>> shared_nodes_;
  double origin_x_ = 0, origin_y_ = 0;
  int columns_ = 1, rows_ = 1;
  std::vector<int> bucket_start_;
  // The vertices bucket by bucket, with their points beside them so that a
  // search reads them in a row; `vertex` is -1 once the vertex is removed.
  struct BucketPoint {
    double x, y;
    int vertex;
  };
  std::vector<BucketPoint> bucket_points_;
  std::vector<int> slot_of_vertex_;
};

}  // namespace

std::vector<PointList> SimplifyBorders(const std::vector<PointList>& chains,
                                       const std::vector<double>& tolerance_px) {
  const double largest =
      tolerance_px.empty() ? 0 : *std::max_element(tolerance_px.begin(), tolerance_px.end());
  if (!(largest > 0)) return chains;
  return Simplifier(chains, tolerance_px, largest).Run(largest * largest);
}

}  // namespace areagraph
