#include "tools/export/snap_rounding.h"

#include <algorithm>
#include <cmath>

namespace areagraph {

namespace {

// Hot pixels are bucketed in squares of this many grid units, so that an
// edge is tested against the hot pixels near it only.
constexpr int64_t kBucketUnits = 64;

GridPoint Rounded(const GridPosition& p) { return {std::llround(p.x), std::llround(p.y)}; }

int64_t BucketOf(double units) {
  return static_cast<int64_t>(std::floor(units / static_cast<double>(kBucketUnits)));
}

// Where the segment a -> b first meets the closed square of side 1 around
// `pixel`, as a parameter in [0, 1]; negative when it misses the square
// (Liang-Barsky clipping).
double EntryIntoPixel(const GridPosition& a, const GridPosition& b, const GridPoint& pixel) {
  double enter = 0, leave = 1;
  const double start[2] = {a.x, a.y}, delta[2] = {b.x - a.x, b.y - a.y};
  const double low[2] = {pixel.first - 0.5, pixel.second - 0.5};
  for (int axis = 0; axis < 2; ++axis) {
    const double high = low[axis] + 1;
    if (delta[axis] == 0) {
      if (start[axis] < low[axis] || start[axis] > high) return -1;
      continue;
    }
    double t0 = (low[axis] - start[axis]) / delta[axis];
    double t1 = (high - start[axis]) / delta[axis];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
    if (enter > leave) return -1;
  }
  return enter;
}

}  // namespace

SnapRounder::SnapRounder(const std::vector<std::vector<GridPosition>>& rings) {
  for (const auto& ring : rings) {
    for (const GridPosition& p : ring) {
      const GridPoint pixel = Rounded(p);
      buckets_[{BucketOf(static_cast<double>(pixel.first)),
                BucketOf(static_cast<double>(pixel.second))}]
          .insert(pixel);
    }
  }
}

std::vector<GridPoint> SnapRounder::Along(const GridPosition& a, const GridPosition& b) const {
  const GridPoint from = Rounded(a), to = Rounded(b);
  std::vector<std::pair<double, GridPoint>> found;
  const int64_t x0 = BucketOf(std::min(a.x, b.x) - 1), x1 = BucketOf(std::max(a.x, b.x) + 1);
  const int64_t y0 = BucketOf(std::min(a.y, b.y) - 1), y1 = BucketOf(std::max(a.y, b.y) + 1);
  for (int64_t bx = x0; bx <= x1; ++bx) {
    for (int64_t by = y0; by <= y1; ++by) {
      const auto bucket = buckets_.find({bx, by});
      if (bucket == buckets_.end()) continue;
      for (const GridPoint& pixel : bucket->second) {
        if (pixel == from || pixel == to) continue;
        const double t = EntryIntoPixel(a, b, pixel);
        if (t >= 0) found.push_back({t, pixel});
      }
    }
  }
  std::sort(found.begin(), found.end());
  std::vector<GridPoint> pixels;
  for (const auto& [t, pixel] : found) pixels.push_back(pixel);
  return pixels;
}

std::vector<GridPoint> SnapRounder::Ring(const std::vector<GridPosition>& ring) const {
  std::vector<GridPoint> out;
  for (size_t i = 0; i < ring.size(); ++i) {
    out.push_back(Rounded(ring[i]));
    for (const GridPoint& pixel : Along(ring[i], ring[(i + 1) % ring.size()])) {
      out.push_back(pixel);
    }
  }
  return out;
}

std::vector<GridPoint> SnapRounder::Line(const std::vector<GridPosition>& line) const {
  std::vector<GridPoint> out;
  for (size_t i = 0; i < line.size(); ++i) {
    out.push_back(Rounded(line[i]));
    if (i + 1 == line.size()) break;
    for (const GridPoint& pixel : Along(line[i], line[i + 1])) out.push_back(pixel);
  }
  return out;
}

}  // namespace areagraph
