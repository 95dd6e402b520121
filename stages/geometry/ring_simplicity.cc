#include "stages/geometry/ring_simplicity.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace areagraph {
namespace {

struct Segment {
  Eigen::Vector2d a, b;
  int ring;
  int index;
};

double Cross(const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
  return u.x() * v.y() - u.y() * v.x();
}

int Orientation(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) {
  const double c = Cross(q - p, r - p);
  return c > 0 ? 1 : (c < 0 ? -1 : 0);
}

// For collinear p, q, r: whether r lies within the bounding box of pq.
bool OnSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) {
  return std::min(p.x(), q.x()) <= r.x() && r.x() <= std::max(p.x(), q.x()) &&
         std::min(p.y(), q.y()) <= r.y() && r.y() <= std::max(p.y(), q.y());
}

bool Touch(const Segment& s, const Segment& t) {
  const int o1 = Orientation(s.a, s.b, t.a), o2 = Orientation(s.a, s.b, t.b);
  const int o3 = Orientation(t.a, t.b, s.a), o4 = Orientation(t.a, t.b, s.b);
  if (o1 != o2 && o3 != o4) return true;
  return (o1 == 0 && OnSegment(s.a, s.b, t.a)) || (o2 == 0 && OnSegment(s.a, s.b, t.b)) ||
         (o3 == 0 && OnSegment(t.a, t.b, s.a)) || (o4 == 0 && OnSegment(t.a, t.b, s.b));
}

}  // namespace

double SignedArea(const PointList& ring) {
  double twice = 0;
  for (size_t i = 0; i < ring.size(); ++i) twice += Cross(ring[i], ring[(i + 1) % ring.size()]);
  return 0.5 * twice;
}

bool RingsAreSimple(const std::vector<PointList>& rings) {
  std::vector<Segment> segments;
  double extent = 0;
  for (size_t r = 0; r < rings.size(); ++r) {
    const PointList& ring = rings[r];
    if (ring.size() < 3) return false;
    for (size_t i = 0; i < ring.size(); ++i) {
      const Eigen::Vector2d& a = ring[i];
      const Eigen::Vector2d& b = ring[(i + 1) % ring.size()];
      if (a == b) return false;
      segments.push_back({a, b, static_cast<int>(r), static_cast<int>(i)});
      extent = std::max(extent, (b - a).norm());
    }
  }
  // Consecutive segments meet only at their shared point: no fold-back.
  for (const PointList& ring : rings) {
    const size_t n = ring.size();
    for (size_t i = 0; i < n; ++i) {
      const Eigen::Vector2d u = ring[(i + 1) % n] - ring[i];
      const Eigen::Vector2d v = ring[(i + 2) % n] - ring[(i + 1) % n];
      if (Cross(u, v) == 0 && u.dot(v) < 0) return false;
    }
  }
  // Bucket segments in a grid of cells about as big as a typical segment.
  const double cell = std::max(2.0, std::min(extent, 16.0));
  std::unordered_map<long long, std::vector<int>> buckets;
  auto key = [](long long cx, long long cy) { return (cx << 32) ^ (cy & 0xffffffffLL); };
  for (size_t s = 0; s < segments.size(); ++s) {
    const Segment& seg = segments[s];
    const long long x0 = std::floor(std::min(seg.a.x(), seg.b.x()) / cell);
    const long long x1 = std::floor(std::max(seg.a.x(), seg.b.x()) / cell);
    const long long y0 = std::floor(std::min(seg.a.y(), seg.b.y()) / cell);
    const long long y1 = std::floor(std::max(seg.a.y(), seg.b.y()) / cell);
    for (long long cx = x0; cx <= x1; ++cx) {
      for (long long cy = y0; cy <= y1; ++cy) buckets[key(cx, cy)].push_back(static_cast<int>(s));
    }
  }
  for (const auto& [unused, members] : buckets) {
    for (size_t i = 0; i < members.size(); ++i) {
      for (size_t j = i + 1; j < members.size(); ++j) {
        const Segment& s = segments[members[i]];
        const Segment& t = segments[members[j]];
        if (s.ring == t.ring) {
          const int n = static_cast<int>(rings[s.ring].size());
          const int gap = std::abs(s.index - t.index);
          if (gap == 1 || gap == n - 1) continue;  // neighbours share one point
        }
        if (Touch(s, t)) return false;
      }
    }
  }
  return true;
}

}  // namespace areagraph
