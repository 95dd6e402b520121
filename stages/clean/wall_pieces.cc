#include "stages/clean/wall_pieces.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "stages/geometry/distance_transform.h"
#include "stages/geometry/furniture_shape.h"
#include "stages/geometry/obstacle_regions.h"
#include "stages/geometry/region_boxes.h"
#include "stages/geometry/wall_thickness.h"

namespace areagraph {
namespace {

int LabelAt(const cv::Mat& labels, const Eigen::Vector2d& p) {
  const int c = static_cast<int>(std::floor(p.x())), r = static_cast<int>(std::floor(p.y()));
  return c >= 0 && r >= 0 && c < labels.cols && r < labels.rows ? labels.at<int>(r, c) : 0;
}

// Whether past the end of `region` in `direction` (+1 or -1 along its axis),
// on its centre line or a line one cell beside it, another region's cell
// lies within `max_gap_px`.
bool MeetsObstaclePastEnd(const cv::Mat& labels, const RegionShape& shape, int region,
                          int direction, double max_gap_px) {
  const Eigen::Vector2d along = direction * shape.axis;
  const Eigen::Vector2d across(-along.y(), along.x());
  for (const int offset : {0, -1, 1}) {
    const Eigen::Vector2d end = shape.centre + 0.5 * shape.length * along + offset * across;
    for (double t = 0; t <= max_gap_px; t += 1) {
      const int label = LabelAt(labels, end + t * along);
      if (label != 0 && label != region) return true;
    }
  }
  return false;
}

// Whether a cell of `label` lies in row r between columns c0 and c1
// (inclusive, clipped to the image).
bool RowHolds(const cv::Mat& labels, int label, int r, int c0, int c1) {
  if (r < 0 || r >= labels.rows) return false;
  const int* row = labels.ptr<int>(r);
  for (int c = std::max(c0, 0); c <= std::min(c1, labels.cols - 1); ++c) {
    if (row[c] == label) return true;
  }
  return false;
}

bool ColumnHolds(const cv::Mat& labels, int label, int c, int r0, int r1) {
  if (c < 0 || c >= labels.cols) return false;
  for (int r = std::max(r0, 0); r <= std::min(r1, labels.rows - 1); ++r) {
    if (labels.ptr<int>(r)[c] == label) return true;
  }
  return false;
}

// `box` (around some cells of `label`) grown to the label's whole region:
// an 8-connected region reaching beyond a box has a cell in the ring just
// outside it.
cv::Rect RegionBox(const cv::Mat& labels, int label, cv::Rect box) {
  for (bool grown = true; grown;) {
    const int left = box.x - 1, right = box.x + box.width;
    const int top = box.y - 1, bottom = box.y + box.height;
    grown = true;
    if (RowHolds(labels, label, top, left, right)) {
      box.y -= 1, box.height += 1;
    } else if (RowHolds(labels, label, bottom, left, right)) {
      box.height += 1;
    } else if (ColumnHolds(labels, label, left, top, bottom)) {
      box.x -= 1, box.width += 1;
    } else if (ColumnHolds(labels, label, right, top, bottom)) {
      box.width += 1;
    } else {
      grown = false;
    }
  }
  return box;
}

// Twice the deepest depth (ObstacleDepth of the map) of the cells of `label`
// inside `box`.
float ThicknessInBox(const cv::Mat& labels, const cv::Mat& depth, int label, const cv::Rect& box) {
  float thickness = 0;
  for (int r = box.y; r < box.y + box.height; ++r) {
    const int* row = labels.ptr<int>(r);
    const float* depth_of = depth.ptr<float>(r);
    for (int c = box.x; c < box.x + box.width; ++c) {
      if (row[c] == label) thickness = std::max(thickness, 2 * depth_of[c]);
    }
  }
  return thickness;
}

}  // namespace

std::vector<uint8_t> WallPieceRegions(const std::string& cells, int width, int height,
                                      const cv::Mat& labels, int label_count,
                                      const std::vector<int>& candidate_cells,
                                      const WallPieceSizes& sizes) {
  // The candidates' cell centres and boxes per region.
  std::vector<int> slot(label_count, -1);
  std::vector<int> regions;
  std::vector<std::vector<cv::Point2f>> site_cells;
  std::vector<cv::Rect> boxes;
  const int* label_of = labels.ptr<int>();
  for (const int index : candidate_cells) {
    const int region = label_of[index];
    const int col = index % width, row = index / width;
    if (slot[region] < 0) {
      slot[region] = int(regions.size());
      regions.push_back(region);
      site_cells.emplace_back();
      boxes.emplace_back(col, row, 1, 1);
    }
    site_cells[slot[region]].emplace_back(col + 0.5f, row + 0.5f);
    boxes[slot[region]] |= cv::Rect(col, row, 1, 1);
  }
  // The map's depth only if some decision needs it.
  cv::Mat map_depth;
  auto depth = [&]() -> const cv::Mat& {
    if (map_depth.empty()) map_depth = ObstacleDepth(ObstacleMask(cells, width, height));
    return map_depth;
  };
  std::optional<double> typical;
  const bool exact = ComputedExactly(cv::Size(width, height));

  std::vector<uint8_t> wall(label_count, 0);
  for (size_t i = 0; i < regions.size(); ++i) {
    const int region = regions[i];
    if (region == 0) continue;
    const cv::Rect box = RegionBox(labels, region, boxes[i]);
    if (box.x == 0 || box.y == 0 || box.x + box.width == width || box.y + box.height == height) {
      continue;
    }
    RegionShape shape;
    FitRegionRectangle(site_cells[i], &shape);
    if (shape.length < sizes.min_length_px || shape.length < kWallPieceElongation * shape.width ||
        !MeetsObstaclePastEnd(labels, shape, region, 1, sizes.max_gap_px) ||
        !MeetsObstaclePastEnd(labels, shape, region, -1, sizes.max_gap_px)) {
      continue;
    }
    // A region's nearest free cells lie within one cell of its box; within
    // the box the exact transform gives the map's values.
    const float thickness = exact ? 2 * float(DeepestDistance(LabelMaskInBox(labels, region, box)))
                                  : ThicknessInBox(labels, depth(), region, box);
    // thickness < max(thinner_than_px, ratio * typical wall).
    if (thickness < sizes.thinner_than_px) {
      wall[region] = 1;
      continue;
    }
    if (!typical) typical = TypicalWallThickness(depth(), sizes.max_wall_px);
    wall[region] = thickness < kFurnitureWallRatio * *typical;
  }
  return wall;
}

}  // namespace areagraph
