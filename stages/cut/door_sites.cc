#include "stages/cut/door_sites.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "stages/geometry/wall_thickness.h"

namespace areagraph {
namespace {

// The map's non-free cells and whether each 8-connected region of them is
// the building's structure.
class WallStructure {
 public:
  WallStructure(const std::string& cells, int width, int height, double min_region_px)
      : width_(width), height_(height) {
    cv::Mat stats, centroids;
    const int count = cv::connectedComponentsWithStats(ObstacleMask(cells, width, height), labels_,
                                                       stats, centroids, 8);
    structure_.assign(count, 0);
    for (int region = 1; region < count; ++region) {
      const int left = stats.at<int>(region, cv::CC_STAT_LEFT);
      const int top = stats.at<int>(region, cv::CC_STAT_TOP);
      const int w = stats.at<int>(region, cv::CC_STAT_WIDTH);
      const int h = stats.at<int>(region, cv::CC_STAT_HEIGHT);
      const bool on_border = left == 0 || top == 0 || left + w == width || top + h == height;
      structure_[region] = on_border || std::max(w, h) >= min_region_px;
    }
  }

  int LabelAt(int col, int row) const {
    return col >= 0 && row >= 0 && col < width_ && row < height_ ? labels_.at<int>(row, col) : 0;
  }
  int LabelAt(const Eigen::Vector2d& p) const {
    return LabelAt(static_cast<int>(std::floor(p.x())), static_cast<int>(std::floor(p.y())));
  }
  bool IsStructure(int label) const { return label > 0 && structure_[label] != 0; }

 private:
  int width_;
  int height_;
  cv::Mat labels_;
  std::vector<uint8_t> structure_;
};

// The nearest non-free cell centre to `p` within `radius` px, optionally only
// on the far side of `p` from `away` (angle above 120 degrees); false if none.
bool NearestObstacle(const WallStructure& walls, const Eigen::Vector2d& p, double radius,
                     const Eigen::Vector2d* away, Eigen::Vector2d* found) {
  double best = radius * radius;
  bool any = false;
  const int r = static_cast<int>(std::ceil(radius));
  const int pc = static_cast<int>(std::floor(p.x())), pr = static_cast<int>(std::floor(p.y()));
  for (int row = pr - r; row <= pr + r; ++row) {
    for (int col = pc - r; col <= pc + r; ++col) {
      if (walls.LabelAt(col, row) == 0) continue;
      const Eigen::Vector2d c(col + 0.5, row + 0.5);
      const Eigen::Vector2d d = c - p;
      const double d2 = d.squaredNorm();
      if (d2 > best) continue;
      if (away != nullptr) {
        const Eigen::Vector2d a = *away - p;
        if (d.dot(a) > -0.5 * d.norm() * a.norm()) continue;
      }
      best = d2, *found = c, any = true;
    }
  }
  return any;
}

// Whether non-free cells run on from `jamb` in `direction` for `run_px`.
bool WallRunsOn(const WallStructure& walls, const Eigen::Vector2d& jamb,
                const Eigen::Vector2d& direction, double run_px) {
  int samples = 0, non_free = 0;
  for (double t = 1; t <= run_px; t += 1, ++samples) {
    non_free += walls.LabelAt(jamb + t * direction) != 0;
  }
  return samples == 0 || non_free >= kJambRunShare * samples;
}

}  // namespace

PointList DoorClosingSites(const proto::RoomWidthEstimate& estimate, const std::string& cells,
                           int width, int height, double resolution_m) {
  PointList sites;
  if (estimate.doors_size() == 0) return sites;
  const WallStructure walls(cells, width, height, kMinWallRegionM / resolution_m);
  const double run_px = kJambRunM / resolution_m;
  for (const proto::DetectedWidth& door : estimate.doors()) {
    const Eigen::Vector2d p(door.position().x(), door.position().y());
    const double reach = 0.5 * door.width_m() / resolution_m + 2;
    Eigen::Vector2d a, b;
    if (!NearestObstacle(walls, p, reach, nullptr, &a)) continue;
    if (!NearestObstacle(walls, p, reach + 1, &a, &b)) continue;
    if (!walls.IsStructure(walls.LabelAt(a)) || !walls.IsStructure(walls.LabelAt(b))) continue;
    const double span = (b - a).norm();
    if (span < 1) continue;
    const Eigen::Vector2d along = (b - a) / span;
    if (!WallRunsOn(walls, a, -along, run_px) || !WallRunsOn(walls, b, along, run_px)) continue;
    const int steps = static_cast<int>(std::ceil(span));
    for (int k = 1; k < steps; ++k) sites.push_back(a + (b - a) * (static_cast<double>(k) / steps));
  }
  return sites;
}

}  // namespace areagraph
