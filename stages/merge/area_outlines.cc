#include "stages/merge/area_outlines.h"

#include <algorithm>
#include <cmath>

#include "stages/geometry/ring_simplicity.h"
#include "stages/merge/border_simplification.h"

namespace areagraph {
namespace {

// Even-odd test of a point against a ring.
bool InsideRing(const PointList& ring, double x, double y) {
  bool inside = false;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Eigen::Vector2d& a = ring[i];
    const Eigen::Vector2d& b = ring[j];
    if ((a.y() > y) != (b.y() > y) && x < (b.x() - a.x()) * (y - a.y()) / (b.y() - a.y()) + a.x()) {
      inside = !inside;
    }
  }
  return inside;
}

// Whether every cell whose centre lies inside `ring` is no area.
bool HoldsNoArea(const PointList& ring, const cv::Mat& labels) {
  double x0 = ring[0].x(), x1 = x0, y0 = ring[0].y(), y1 = y0;
  for (const Eigen::Vector2d& p : ring) {
    x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x());
    y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
  }
  const int c0 = std::max(0, static_cast<int>(std::floor(x0)));
  const int c1 = std::min(labels.cols - 1, static_cast<int>(std::ceil(x1)));
  const int r0 = std::max(0, static_cast<int>(std::floor(y0)));
  const int r1 = std::min(labels.rows - 1, static_cast<int>(std::ceil(y1)));
  for (int r = r0; r <= r1; ++r) {
    for (int c = c0; c <= c1; ++c) {
      if (labels.at<int>(r, c) != 0 && InsideRing(ring, c + 0.5, r + 0.5)) return false;
    }
  }
  return true;
}

double Perimeter(const PointList& ring) {
  double length = 0;
  for (size_t i = 0; i < ring.size(); ++i) length += (ring[(i + 1) % ring.size()] - ring[i]).norm();
  return length;
}

// Which rings of one area make its polygon.
struct RingRoles {
  int outer = -1;
  std::vector<int> holes;
};

}  // namespace

PartitionOutlines SimplifiedOutlines(const PlanarPartition& partition, const cv::Mat& labels,
                                     double tolerance_px, double min_hole_px2,
                                     const std::function<void()>& labels_done) {
  std::vector<PointList> traced = ChainPoints(partition);
  const size_t area_count = partition.rings.size();
  PartitionOutlines result;
  std::vector<RingRoles> roles(area_count);
  std::vector<bool> dropped(traced.size(), false);
  // Kept holes that hold no area, (area, ring): they must stay at least the
  // minimum size.
  std::vector<std::pair<int, int>> sized_holes;
  for (size_t k = 0; k < area_count; ++k) {
    const auto& rings = partition.rings[k];
    std::vector<double> areas;
    for (const auto& ring : rings) areas.push_back(SignedArea(RingPoints(ring, traced)));
    for (size_t i = 0; i < rings.size(); ++i) {
      if (areas[i] > 0 && (roles[k].outer < 0 || areas[i] > areas[roles[k].outer])) {
        roles[k].outer = static_cast<int>(i);
      }
    }
    for (size_t i = 0; i < rings.size(); ++i) {
      // A second positive ring would be a second piece of the area; areas
      // are one 4-connected piece each, so there is none.
      if (!(areas[i] < 0)) continue;
      // No other area along the hole's border (an area nested further in is
      // looked for only in small holes, where it is cheap).
      const bool obstacle =
          std::all_of(rings[i].begin(), rings[i].end(), [&](const ChainSide& side) {
            const BorderChain& chain = partition.chains[side.chain];
            return (side.reversed ? chain.right : chain.left) == 0;
          });
      if (obstacle && -areas[i] < min_hole_px2 &&
          HoldsNoArea(RingPoints(rings[i], traced), labels)) {
        for (const ChainSide& side : rings[i]) dropped[side.chain] = true;
        ++result.dropped_holes;
        continue;
      }
      roles[k].holes.push_back(static_cast<int>(i));
      if (obstacle) sized_holes.emplace_back(static_cast<int>(k), static_cast<int>(i));
    }
  }
  if (labels_done) labels_done();
  // A ring simplified within t loses at most t times its perimeter of area:
  // a thin obstacle that this could shrink below the minimum gets half a
  // cell, or keeps every point.
  std::vector<double> tolerance(traced.size(), tolerance_px);
  for (const auto& [k, hole] : sized_holes) {
    const auto& ring = partition.rings[k][hole];
    const PointList points = RingPoints(ring, traced);
    const double area = -SignedArea(points), perimeter = Perimeter(points);
    double allowed = tolerance_px;
    if (area - allowed * perimeter < min_hole_px2) allowed = std::min(allowed, 0.5);
    if (area - allowed * perimeter < min_hole_px2) allowed = 0;
    for (const ChainSide& side : ring) tolerance[side.chain] = allowed;
  }
  std::vector<int> kept;
  std::vector<PointList> borders;
  std::vector<double> tolerances;
  for (size_t c = 0; c < traced.size(); ++c) {
    if (dropped[c]) continue;
    kept.push_back(static_cast<int>(c));
    borders.push_back(std::move(traced[c]));
    tolerances.push_back(tolerance[c]);
  }
  std::vector<PointList> simplified = SimplifyBorders(borders, tolerances);
  result.chains.assign(traced.size(), {});
  for (size_t i = 0; i < kept.size(); ++i) result.chains[kept[i]] = std::move(simplified[i]);

  result.areas.resize(area_count);
  for (size_t k = 0; k < area_count; ++k) {
    if (roles[k].outer < 0) continue;
    const auto& rings = partition.rings[k];
    result.areas[k].outer = RingPoints(rings[roles[k].outer], result.chains);
    for (const int hole : roles[k].holes) {
      result.areas[k].holes.push_back(RingPoints(rings[hole], result.chains));
    }
  }
  return result;
}

}  // namespace areagraph
