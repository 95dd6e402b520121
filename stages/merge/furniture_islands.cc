#include "stages/merge/furniture_islands.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <new>
#include <opencv2/imgproc.hpp>

#include "stages/geometry/distance_transform.h"
#include "stages/geometry/enclosed_pockets.h"
#include "stages/geometry/wall_thickness.h"

namespace areagraph {
namespace {

// What the walks found per cell.
enum : uint8_t { kWalked = 1, kInWalk = 2, kIsland = 4 };

// One flag byte per cell of the map, zeroed by calloc: pages that no walk
// reaches are never touched (a walk reaches a few thousand cells).
class CellFlags {
 public:
  explicit CellFlags(const cv::Size& size)
      : cols_(size.width), flags_(static_cast<uint8_t*>(std::calloc(size.area(), 1)), &std::free) {
    if (!flags_) throw std::bad_alloc();
  }
  uint8_t& at(const cv::Point& p) { return flags_.get()[static_cast<size_t>(p.y) * cols_ + p.x]; }

 private:
  int cols_;
  std::unique_ptr<uint8_t, decltype(&std::free)> flags_;
};

// An 8-connected region of a mask's non-zero cells that may be an island
// (it touches no border and its box is at most the island length): its
// cells in row-major order and their bounding box.
struct Region {
  std::vector<cv::Point> cells;
  cv::Rect box;
};

// Walks the region of `mask` that holds `start` (non-zero, not walked yet)
// and marks its cells kWalked. Stops, with false, once the region touches
// the border, its box outgrows `max_px`, or it meets a cell walked before
// (a region that stopped so before): no island. Else `region` is all of it.
// Depth first: a wall or the map's outside outgrows the box after about
// max_px steps, where a breadth-first walk would fill a disk of that radius.
bool WalkRegion(const cv::Mat& mask, const cv::Point& start, double max_px, CellFlags& flags,
                Region* region) {
  const int width = mask.cols, height = mask.rows;
  std::vector<cv::Point>& cells = region->cells;
  cells.assign(1, start);
  std::vector<cv::Point> todo(1, start);
  flags.at(start) |= kInWalk;
  int left = start.x, right = start.x, top = start.y, bottom = start.y;
  bool island = true;
  while (!todo.empty() && island) {
    const cv::Point p = todo.back();
    todo.pop_back();
    if (p.x == 0 || p.y == 0 || p.x == width - 1 || p.y == height - 1) {
      island = false;
      break;
    }
    for (int dy = -1; dy <= 1 && island; ++dy) {
      const uint8_t* row = mask.ptr<uint8_t>(p.y + dy);
      for (int dx = -1; dx <= 1; ++dx) {
        const cv::Point q(p.x + dx, p.y + dy);
        if (row[q.x] == 0) continue;
        uint8_t& flag = flags.at(q);
        if (flag & kInWalk) continue;
        if (flag & kWalked) {
          island = false;
          break;
        }
        flag |= kInWalk;
        cells.push_back(q);
        todo.push_back(q);
        left = std::min(left, q.x), right = std::max(right, q.x);
        top = std::min(top, q.y), bottom = std::max(bottom, q.y);
        if (std::max(right - left + 1, bottom - top + 1) > max_px) {
          island = false;
          break;
        }
      }
    }
  }
  for (const cv::Point& p : cells) flags.at(p) = (flags.at(p) & ~kInWalk) | kWalked;
  if (!island) return false;
  std::sort(cells.begin(), cells.end(), [](const cv::Point& a, const cv::Point& b) {
    return a.y != b.y ? a.y < b.y : a.x < b.x;
  });
  region->box = cv::Rect(left, top, right - left + 1, bottom - top + 1);
  return true;
}

// The regions of `mask` that hold one of `cells` (inside the map) and may be
// islands.
std::vector<Region> CandidateRegions(const cv::Mat& mask, const std::vector<cv::Point>& cells,
                                     double max_px, CellFlags& flags) {
  const cv::Rect map(0, 0, mask.cols, mask.rows);
  std::vector<Region> candidates;
  Region region;
  for (const cv::Point& p : cells) {
    if (!map.contains(p) || mask.at<uint8_t>(p) == 0 || (flags.at(p) & kWalked)) continue;
    if (WalkRegion(mask, p, max_px, flags, &region)) candidates.push_back(std::move(region));
  }
  return candidates;
}

// Whether a region fills kMinFurnitureSolidity of its smallest enclosing
// rectangle and, unless `max_elongation` is 0, is at most that many times
// as long as the rectangle is wide: a piece of wall between two doors is
// long and narrow, a desk is not.
bool IslandShaped(const Region& region, double max_elongation) {
  const cv::RotatedRect box = cv::minAreaRect(region.cells);
  const double box_cells = (box.size.width + 1) * (box.size.height + 1);
  const int area = static_cast<int>(region.cells.size());
  if (!(area >= kMinFurnitureSolidity * box_cells)) return false;
  const double longer = std::max(box.size.width, box.size.height) + 1;
  const double shorter = std::min(box.size.width, box.size.height) + 1;
  return !(max_elongation > 0 && longer > max_elongation * shorter);
}

// Marks kIsland on the cells of the regions of `mask` around `cells` that
// are islands: at least `min_thickness_px` thick (twice the deepest of
// `deepest`, which gives each candidate's) and shaped as IslandShaped says.
template <typename Deepest>
void MarkIslands(const cv::Mat& mask, const std::vector<cv::Point>& cells, double min_thickness_px,
                 double max_px, double max_elongation, Deepest deepest_of, CellFlags& flags) {
  const std::vector<Region> candidates = CandidateRegions(mask, cells, max_px, flags);
  const std::vector<float> deepest = deepest_of(candidates);
  for (size_t k = 0; k < candidates.size(); ++k) {
    if (!(2 * deepest[k] >= min_thickness_px)) continue;
    if (!IslandShaped(candidates[k], max_elongation)) continue;
    for (const cv::Point& p : candidates[k].cells) flags.at(p) |= kIsland;
  }
}

}  // namespace

cv::Mat ObstaclesBeforeCleaning(const proto::CleanedMap& map) {
  const int width = map.frame().width_px(), height = map.frame().height_px();
  cv::Mat obstacle = ObstacleMask(map.cells(), width, height);
  for (const auto* list : {&map.removed_outlier_cells(), &map.removed_furniture_cells()}) {
    for (const int index : *list) {
      if (index >= 0 && index < width * height) obstacle.data[index] = 255;
    }
  }
  return obstacle;
}

std::vector<uint8_t> FurnitureIslandsAt(const proto::CleanedMap& map, double max_length_m,
                                        bool fill_outlines, double max_elongation,
                                        const std::vector<cv::Point>& cells) {
  const int width = map.frame().width_px(), height = map.frame().height_px();
  const double resolution_m = map.frame().resolution_m();
  cv::Mat obstacle = ObstaclesBeforeCleaning(map);
  const double max_px = max_length_m / resolution_m;
  if (fill_outlines) FillEnclosedPockets(max_px, &obstacle);
  const cv::Rect inside(0, 0, width, height);
  std::vector<uint8_t> values(cells.size(), 0);
  double min_thickness_px = 0;
  {
    // One distance transform of the obstacles for the wall thickness and the islands.
    const cv::Mat depth = ObstacleDepth(obstacle);
    min_thickness_px = std::max(
        kMinFurnitureThicknessM / resolution_m,
        kFurnitureWallRatio * TypicalWallThickness(depth, kMaxWallThicknessM / resolution_m));
    CellFlags flags(obstacle.size());
    auto depth_of = [&](const std::vector<Region>& regions) {
      std::vector<float> deepest(regions.size(), 0);
      for (size_t k = 0; k < regions.size(); ++k) {
        for (const cv::Point& p : regions[k].cells) {
          deepest[k] = std::max(deepest[k], depth.at<float>(p));
        }
      }
      return deepest;
    };
    MarkIslands(obstacle, cells, min_thickness_px, max_px, max_elongation, depth_of, flags);
    for (size_t i = 0; i < cells.size(); ++i) {
      if (inside.contains(cells[i]) && (flags.at(cells[i]) & kIsland)) values[i] = 1;
    }
  }
  return values;
}

cv::Mat FurnitureIslandCells(const proto::CleanedMap& map, double max_length_m, bool fill_outlines,
                             double max_elongation) {
  const int width = map.frame().width_px(), height = map.frame().height_px();
  std::vector<cv::Point> cells;
  cells.reserve(static_cast<size_t>(width) * height);
  for (int r = 0; r < height; ++r) {
    for (int c = 0; c < width; ++c) cells.emplace_back(c, r);
  }
  const std::vector<uint8_t> values =
      FurnitureIslandsAt(map, max_length_m, fill_outlines, max_elongation, cells);
  return cv::Mat(height, width, CV_8U, const_cast<uint8_t*>(values.data())).clone();
}

}  // namespace areagraph
