#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "stages/geometry/obstacle_regions.h"

namespace areagraph {

// Probes of the walls around an opening, shared by the door, wall gap and
// mouth finders (stages/cut/door_sites.h, stages/cut/mouth_sites.h).

// The map's non-free cells and whether each 8-connected region of them is
// the building's structure.
class WallStructure {
 public:
  WallStructure(const ObstacleLabels& obstacles, double min_region_px,
                const cv::Mat* free_spaces = nullptr)
      : width_(obstacles.labels.cols),
        height_(obstacles.labels.rows),
        labels_(obstacles.labels),
        free_spaces_(free_spaces != nullptr ? *free_spaces : cv::Mat()) {
    const int count = obstacles.count, width = width_, height = height_;
    const cv::Mat& stats = obstacles.stats;
    structure_.assign(count, 0);
    longest_.assign(count, 0);
    for (int region = 1; region < count; ++region) {
      const int left = stats.at<int>(region, cv::CC_STAT_LEFT);
      const int top = stats.at<int>(region, cv::CC_STAT_TOP);
      const int w = stats.at<int>(region, cv::CC_STAT_WIDTH);
      const int h = stats.at<int>(region, cv::CC_STAT_HEIGHT);
      const bool on_border = left == 0 || top == 0 || left + w == width || top + h == height;
      structure_[region] = on_border || std::max(w, h) >= min_region_px;
      longest_[region] = std::max(w, h);
    }
  }

  int LabelAt(int col, int row) const {
    return col >= 0 && row >= 0 && col < width_ && row < height_ ? labels_.at<int>(row, col) : 0;
  }
  int LabelAt(const Eigen::Vector2d& p) const {
    return LabelAt(static_cast<int>(std::floor(p.x())), static_cast<int>(std::floor(p.y())));
  }
  bool IsStructure(int label) const { return label > 0 && structure_[label] != 0; }
  // The longer side of the region's bounding box (px); 0 for free cells.
  int Longest(int label) const { return label > 0 ? longest_[label] : 0; }
  // The free space (LabelFreeSpaces) holding `p`; 0 when `p` is not free or
  // free spaces are not told apart.
  int SpaceAt(const Eigen::Vector2d& p) const {
    const int col = static_cast<int>(std::floor(p.x())), row = static_cast<int>(std::floor(p.y()));
    if (free_spaces_.empty() || col < 0 || row < 0 || col >= width_ || row >= height_) return 0;
    return free_spaces_.at<int>(row, col);
  }
  // Whether `p` is behind a wall as seen from free space `space`: non-free,
  // or free but not reachable from `space` (space 0: only non-free).
  bool Beyond(const Eigen::Vector2d& p, int space) const {
    if (LabelAt(p) != 0) return true;
    const int other = space > 0 ? SpaceAt(p) : 0;
    return other > 0 && other != space;
  }

 private:
  int width_;
  int height_;
  // Shared with the caller's labels, read only.
  cv::Mat labels_;
  cv::Mat free_spaces_;
  std::vector<uint8_t> structure_;
  std::vector<int> longest_;
};

// The nearest non-free cell centre to `p` within `radius` px, optionally only
// on the far side of `p` from `away` (angle above 120 degrees); false if none.
bool NearestObstacle(const WallStructure& walls, const Eigen::Vector2d& p, double radius,
                     const Eigen::Vector2d* away, Eigen::Vector2d* found);

// Whether non-free cells run on from `jamb` in `direction` for `run_px`.
// Free cells that the door's free space `space` cannot reach count as
// non-free (space 0: none do): they lie behind a wall drawn as a thin line,
// the outside of a map whose outside is drawn free, or the inside of a block
// drawn as a hollow outline.
bool WallRunsOn(const WallStructure& walls, const Eigen::Vector2d& jamb,
                const Eigen::Vector2d& direction, double run_px, int space);

// How far non-free cells run from `from` in `direction` (px, whole steps),
// or -1 when they still run at `limit_px` (no free cell within reach).
double NonFreeRun(const WallStructure& walls, const Eigen::Vector2d& from,
                  const Eigen::Vector2d& direction, double limit_px);

// Whether the wall at `probe` is at most `max_thickness_px` thick across
// `outward` with free cells on both sides.
bool IsThinAt(const WallStructure& walls, const Eigen::Vector2d& probe,
              const Eigen::Vector2d& outward, double max_thickness_px);

// Whether `jamb` is the end of a thin wall running on away from the gap in
// `outward`: thin (IsThinAt) from the jamb on for `run_px` (kJambRunM; a
// partition wall meeting a corridor's wall beside a door is thick at the
// jamb).
bool IsThinWallEnd(const WallStructure& walls, const Eigen::Vector2d& jamb,
                   const Eigen::Vector2d& outward, double run_px, double max_thickness_px);

// Which side of the line through a jamb (along `outward`, away from the
// opening) a wall leaves it on for `depth_px` (+1 along the line's left
// normal, -1 along its right one, 0 neither or both), where the wall on the
// other side is at most `max_thickness_px` thick: the end of a side wall of
// the space behind a mouth, with the wall line's thickness on the far side.
int SideWallAt(const WallStructure& walls, const Eigen::Vector2d& jamb,
               const Eigen::Vector2d& outward, double depth_px, double max_thickness_px, int space);

// How far free cells run from `from` along `direction` (px, whole steps),
// up to `limit_px`, as seen from free space `space`.
double FreeRun(const WallStructure& walls, const Eigen::Vector2d& from,
               const Eigen::Vector2d& direction, double limit_px, int space);

// Whether the space behind a mouth from `a` to `b` runs on deeper than
// kCorridorElongation (stages/geometry/corridor_shape.h) times its width along
// `behind`: a corridor (a side corridor meeting another one, a wing corridor
// opening into a hall), not a room. Probed at the middle and the quarters of the mouth, the deepest
// counting, so that furniture in a room does not make it shallow.
bool CorridorBehind(const WallStructure& walls, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                    const Eigen::Vector2d& behind, int space);

}  // namespace areagraph
