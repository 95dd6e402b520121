#include "stages/merge/region_outline.h"

#include <algorithm>
#include <cmath>

#include "stages/geometry/ring_simplicity.h"

namespace areagraph {
namespace {

// Unit steps between cell corners, as bits: +x, +y, -x, -y.
constexpr int kStepX[4] = {1, 0, -1, 0};
constexpr int kStepY[4] = {0, 1, 0, -1};
// How far a ring stays off a corner where two cells touch diagonally (px).
constexpr double kCornerCut = 0.05;

// Drops points that lie on the straight line through their neighbours.
PointList WithoutCollinearPoints(const PointList& ring) {
  PointList out;
  const size_t n = ring.size();
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d& prev = ring[(i + n - 1) % n];
    const Eigen::Vector2d& next = ring[(i + 1) % n];
    const Eigen::Vector2d u = ring[i] - prev, v = next - ring[i];
    if (std::abs(u.x() * v.y() - u.y() * v.x()) < 1e-12 && u.dot(v) > 0) continue;
    out.push_back(ring[i]);
  }
  return out;
}

double DistanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                         const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

// Douglas-Peucker on ring[first..last] (indices modulo the ring size):
// marks the points to keep.
void MarkKept(const PointList& ring, size_t first, size_t last, double tolerance,
              std::vector<bool>* keep) {
  const size_t n = ring.size();
  double worst = -1;
  size_t worst_at = first;
  for (size_t i = first + 1; i < last; ++i) {
    const double d = DistanceToSegment(ring[i % n], ring[first % n], ring[last % n]);
    if (d > worst) worst = d, worst_at = i;
  }
  if (worst <= tolerance) return;
  (*keep)[worst_at % n] = true;
  MarkKept(ring, first, worst_at, tolerance, keep);
  MarkKept(ring, worst_at, last, tolerance, keep);
}

// Douglas-Peucker for a closed ring, anchored at its first point and the
// point farthest from it.
PointList SimplifyRing(const PointList& ring, double tolerance) {
  const size_t n = ring.size();
  if (n < 4) return ring;
  size_t far = 0;
  for (size_t i = 1; i < n; ++i) {
    if ((ring[i] - ring[0]).squaredNorm() > (ring[far] - ring[0]).squaredNorm()) far = i;
  }
  std::vector<bool> keep(n, false);
  keep[0] = keep[far] = true;
  MarkKept(ring, 0, far, tolerance, &keep);
  MarkKept(ring, far, n, tolerance, &keep);
  PointList out;
  for (size_t i = 0; i < n; ++i) {
    if (keep[i]) out.push_back(ring[i]);
  }
  return out;
}

}  // namespace

RegionOutline TraceRegionOutline(const cv::Mat& labels, int label, const cv::Rect& box) {
  const int w = box.width, h = box.height;
  auto inside = [&](int c, int r) {
    return c >= 0 && r >= 0 && c < w && r < h && labels.at<int>(box.y + r, box.x + c) == label;
  };
  // Outgoing boundary steps at each corner of the box, (w + 1) x (h + 1);
  // every step keeps the region on its right on screen.
  const int corner_cols = w + 1;
  std::vector<unsigned char> out((w + 1) * (h + 1), 0), used((w + 1) * (h + 1), 0);
  auto corner = [&](int x, int y) { return y * corner_cols + x; };
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      if (!inside(c, r)) continue;
      if (!inside(c, r - 1)) out[corner(c, r)] |= 1;          // top: +x
      if (!inside(c + 1, r)) out[corner(c + 1, r)] |= 2;      // right: +y
      if (!inside(c, r + 1)) out[corner(c + 1, r + 1)] |= 4;  // bottom: -x
      if (!inside(c - 1, r)) out[corner(c, r + 1)] |= 8;      // left: -y
    }
  }

  RegionOutline outline;
  std::vector<PointList> rings;
  for (int start = 0; start < static_cast<int>(out.size()); ++start) {
    for (int start_dir = 0; start_dir < 4; ++start_dir) {
      if (!(out[start] & (1 << start_dir)) || (used[start] & (1 << start_dir))) continue;
      // Each step adds the corner it arrives at; the last one closes the ring.
      PointList ring;
      int at = start, dir = start_dir;
      do {
        used[at] |= static_cast<unsigned char>(1 << dir);
        const int x = at % corner_cols + kStepX[dir], y = at / corner_cols + kStepY[dir];
        const Eigen::Vector2d point(box.x + x, box.y + y);
        const int next = corner(x, y);
        const unsigned char options = out[next];
        int next_dir = 0;
        if (options == ((1 << ((dir + 1) % 4)) | (1 << ((dir + 3) % 4)))) {
          // Two ways on: cells meet diagonally here. Turn right (hug the cell
          // just walked along) and keep off the shared corner point.
          next_dir = (dir + 1) % 4;
          ring.push_back(point - kCornerCut * Eigen::Vector2d(kStepX[dir], kStepY[dir]));
          ring.push_back(point + kCornerCut * Eigen::Vector2d(kStepX[next_dir], kStepY[next_dir]));
        } else {
          while (next_dir < 4 && !(options & (1 << next_dir))) ++next_dir;
          if (next_dir == 4) break;  // cannot happen: boundaries are closed
          ring.push_back(point);
        }
        at = next;
        dir = next_dir;
      } while (at != start || dir != start_dir);
      rings.push_back(WithoutCollinearPoints(ring));
    }
  }

  // The outer ring is the one with the largest (positive) area.
  int outer = -1;
  for (size_t i = 0; i < rings.size(); ++i) {
    if (outer < 0 || SignedArea(rings[i]) > SignedArea(rings[outer])) outer = static_cast<int>(i);
  }
  if (outer < 0) return outline;
  outline.outer = rings[outer];
  for (size_t i = 0; i < rings.size(); ++i) {
    if (static_cast<int>(i) != outer && SignedArea(rings[i]) < 0) outline.holes.push_back(rings[i]);
  }
  return outline;
}

RegionOutline SimplifyOutline(const RegionOutline& outline, double tolerance_px) {
  auto simplify = [&](const PointList& ring) { return SimplifyRing(ring, tolerance_px); };
  RegionOutline simplified{simplify(outline.outer), {}};
  std::vector<PointList> rings{simplified.outer};
  for (const PointList& hole : outline.holes) {
    simplified.holes.push_back(simplify(hole));
    rings.push_back(simplified.holes.back());
  }
  if (!RingsAreSimple(rings) || !(SignedArea(simplified.outer) > 0)) return outline;
  for (const PointList& hole : simplified.holes) {
    if (!(SignedArea(hole) < 0)) return outline;
  }
  return simplified;
}

}  // namespace areagraph
