#include "stages/merge/open_borders.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace areagraph {
namespace {

// Whether every cell within `clearance_px` of `p` (nearest point of the
// cell's square strictly nearer) belongs to an area.
bool BodyFits(const cv::Mat& labels, const Eigen::Vector2d& p, double clearance_px) {
  // A cell exactly at the clearance is outside the body, whatever the
  // rounding of metres to pixels.
  const double reach = clearance_px - 1e-9;
  const int c0 = static_cast<int>(std::floor(p.x() - reach));
  const int c1 = static_cast<int>(std::ceil(p.x() + reach));
  const int r0 = static_cast<int>(std::floor(p.y() - reach));
  const int r1 = static_cast<int>(std::ceil(p.y() + reach));
  for (int r = r0; r < r1; ++r) {
    const double dy = std::max({r - p.y(), 0.0, p.y() - (r + 1)});
    for (int c = c0; c < c1; ++c) {
      const double dx = std::max({c - p.x(), 0.0, p.x() - (c + 1)});
      if (dx * dx + dy * dy >= reach * reach) continue;
      if (r < 0 || c < 0 || r >= labels.rows || c >= labels.cols) return false;
      if (labels.at<int>(r, c) == 0) return false;
    }
  }
  return true;
}

// Whether the body fits at some point of `points`, tried every half cell.
bool FitsSomewhere(const cv::Mat& labels, const PointList& points, double clearance_px) {
  for (size_t i = 0; i + 1 < points.size(); ++i) {
    const Eigen::Vector2d step = points[i + 1] - points[i];
    const int samples = std::max(1, static_cast<int>(std::ceil(2 * step.norm())));
    for (int s = 0; s < samples; ++s) {
      if (BodyFits(labels, points[i] + step * (static_cast<double>(s) / samples), clearance_px)) {
        return true;
      }
    }
  }
  return !points.empty() && BodyFits(labels, points.back(), clearance_px);
}

// The point halfway along a polyline.
Eigen::Vector2d Halfway(const PointList& points) {
  double length = 0;
  for (size_t i = 0; i + 1 < points.size(); ++i) length += (points[i + 1] - points[i]).norm();
  double left = length / 2;
  for (size_t i = 0; i + 1 < points.size(); ++i) {
    const double piece = (points[i + 1] - points[i]).norm();
    if (left <= piece && piece > 0) return points[i] + (points[i + 1] - points[i]) * (left / piece);
    left -= piece;
  }
  return points.back();
}

}  // namespace

std::vector<bool> PassableChains(const PlanarPartition& partition, const cv::Mat& labels,
                                 double clearance_px) {
  std::vector<bool> passable(partition.chains.size(), false);
  if (!(clearance_px > 0)) return passable;
  for (size_t c = 0; c < partition.chains.size(); ++c) {
    const BorderChain& chain = partition.chains[c];
    if (chain.left == 0 || chain.right == 0 || chain.left == chain.right) continue;
    passable[c] = FitsSomewhere(labels, chain.points, clearance_px);
  }
  return passable;
}

std::vector<PassageOnBorder> OpenBorderPassages(const PlanarPartition& partition,
                                                const std::vector<bool>& passable,
                                                const std::vector<PointList>& chain_points,
                                                const std::vector<int>& label_of_area,
                                                const std::vector<PassageOnBorder>& placed) {
  std::map<int, int> area_of_label;
  for (size_t id = 0; id < label_of_area.size(); ++id) {
    area_of_label[label_of_area[id]] = static_cast<int>(id);
  }
  std::set<int> opened;
  for (const PassageOnBorder& p : placed) {
    if (p.chain >= 0) opened.insert(p.chain);
  }
  std::vector<PassageOnBorder> passages;
  for (size_t c = 0; c < partition.chains.size(); ++c) {
    const PointList& points = chain_points[c];
    if (!passable[c] || opened.count(static_cast<int>(c)) || points.size() < 2) continue;
    const auto right = area_of_label.find(partition.chains[c].right);
    const auto left = area_of_label.find(partition.chains[c].left);
    if (right == area_of_label.end() || left == area_of_label.end()) continue;
    PassagePlan passage;
    passage.area_a = right->second;
    passage.area_b = left->second;
    passage.point = Halfway(points);
    passage.side_a = points.front();
    passage.side_b = points.back();
    passage.width_px = (points.back() - points.front()).norm();
    passages.push_back({passage, static_cast<int>(c)});
  }
  return passages;
}

}  // namespace areagraph
