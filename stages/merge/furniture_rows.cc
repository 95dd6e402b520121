#include "stages/merge/furniture_rows.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "stages/geometry/disjoint_sets.h"
#include "stages/geometry/distance_transform.h"
#include "stages/geometry/wall_thickness.h"
#include "stages/merge/furniture_gap_joining.h"
#include "stages/merge/furniture_islands.h"

namespace areagraph {
namespace {

// A free-standing block long enough to be a row: its label, its smallest
// enclosing rectangle (centre, unit axis along its longer side, length).
struct RowCandidate {
  int label = 0;
  cv::Point2d centre;
  cv::Point2d axis;
  double length = 0;
};

// Whether two candidates stand side by side in one stack: within the pitch
// across, overlapping along the first one's axis (blocks end to end, as a
// wall broken by doors, do not overlap).
bool InOneStack(const RowCandidate& a, const RowCandidate& b, double max_pitch_px) {
  const cv::Point2d offset = b.centre - a.centre;
  const double along = offset.dot(a.axis);
  const double across = std::abs(offset.x * a.axis.y - offset.y * a.axis.x);
  if (across > max_pitch_px) return false;
  const double overlap =
      std::min(a.length / 2, along + b.length / 2) - std::max(-a.length / 2, along - b.length / 2);
  return overlap > 0;
}

// Whether the cell under a jamb, or one of its 8 neighbours, is a row's.
bool OnRow(const cv::Mat& rows, const Eigen::Vector2d& jamb) {
  const int col = static_cast<int>(std::floor(jamb.x()));
  const int row = static_cast<int>(std::floor(jamb.y()));
  for (int dr = -1; dr <= 1; ++dr) {
    for (int dc = -1; dc <= 1; ++dc) {
      const cv::Point cell(col + dc, row + dr);
      if (cell.inside(cv::Rect(0, 0, rows.cols, rows.rows)) && rows.at<uint8_t>(cell) != 0) {
        return true;
      }
    }
  }
  return false;
}

}  // namespace

cv::Mat FurnitureRowCells(const proto::CleanedMap& map, double min_elongation) {
  const int width = map.frame().width_px(), height = map.frame().height_px();
  const double resolution_m = map.frame().resolution_m();
  cv::Mat obstacle = ObstaclesBeforeCleaning(map);
  cv::Mat labels, stats, centroids;
  const int count = cv::connectedComponentsWithStats(obstacle, labels, stats, centroids, 8, CV_32S);
  const double min_thickness_px = kMinFurnitureThicknessM / resolution_m;
  // A row is longer than `min_elongation` times its least thickness: most
  // regions (specks, desks) are too short to be measured at all.
  const double min_length_px = min_elongation * min_thickness_px;
  std::vector<int> free_standing;
  for (int label = 1; label < count; ++label) {
    const int left = stats.at<int>(label, cv::CC_STAT_LEFT);
    const int top = stats.at<int>(label, cv::CC_STAT_TOP);
    const int w = stats.at<int>(label, cv::CC_STAT_WIDTH);
    const int h = stats.at<int>(label, cv::CC_STAT_HEIGHT);
    if (left == 0 || top == 0 || left + w == width || top + h == height) continue;
    if (std::hypot(w, h) < min_length_px) continue;
    free_standing.push_back(label);
  }
  cv::Mat rows = cv::Mat::zeros(height, width, CV_8U);
  if (free_standing.empty()) return rows;
  std::vector<RowCandidate> candidates;
  std::vector<cv::Point> cells;
  for (const int label : free_standing) {
    const cv::Rect box(
        stats.at<int>(label, cv::CC_STAT_LEFT), stats.at<int>(label, cv::CC_STAT_TOP),
        stats.at<int>(label, cv::CC_STAT_WIDTH), stats.at<int>(label, cv::CC_STAT_HEIGHT));
    // The region alone, with a free border: free cells are all around a
    // free-standing region, so its depth there is its depth in the map.
    cv::Mat region = cv::Mat::zeros(box.height + 2, box.width + 2, CV_8U);
    cells.clear();
    for (int r = box.y; r < box.y + box.height; ++r) {
      for (int c = box.x; c < box.x + box.width; ++c) {
        if (labels.at<int>(r, c) != label) continue;
        cells.emplace_back(c, r);
        region.at<uint8_t>(r - box.y + 1, c - box.x + 1) = 255;
      }
    }
    const cv::RotatedRect rect = cv::minAreaRect(cells);
    const double longer = std::max(rect.size.width, rect.size.height) + 1;
    const double shorter = std::min(rect.size.width, rect.size.height) + 1;
    if (!(longer > min_elongation * shorter)) continue;
    if (!(2 * DeepestDistance(region) >= min_thickness_px)) continue;
    // The rectangle's angle is that of its `width` side.
    const double angle =
        rect.angle * CV_PI / 180.0 + (rect.size.width >= rect.size.height ? 0 : CV_PI / 2);
    candidates.push_back({label, rect.center, {std::cos(angle), std::sin(angle)}, longer});
  }
  DisjointSets stacks(candidates.size());
  const double max_pitch_px = kMaxRowPitchM / resolution_m;
  for (size_t i = 0; i < candidates.size(); ++i) {
    for (size_t j = i + 1; j < candidates.size(); ++j) {
      if (InOneStack(candidates[i], candidates[j], max_pitch_px)) stacks.Union(i, j);
    }
  }
  std::vector<int> stack_size(candidates.size(), 0);
  for (size_t k = 0; k < candidates.size(); ++k) ++stack_size[stacks.Find(k)];
  for (size_t k = 0; k < candidates.size(); ++k) {
    if (stack_size[stacks.Find(k)] < kMinStackRows) continue;
    const int label = candidates[k].label;
    const cv::Rect box(
        stats.at<int>(label, cv::CC_STAT_LEFT), stats.at<int>(label, cv::CC_STAT_TOP),
        stats.at<int>(label, cv::CC_STAT_WIDTH), stats.at<int>(label, cv::CC_STAT_HEIGHT));
    rows(box).setTo(1, labels(box) == label);
  }
  return rows;
}

void JoinAreasAtFurnitureRows(const proto::CutGraph& graph, const PlanModel& model,
                              const cv::Mat& rows, std::vector<bool> closed, double max_piece_m2,
                              AreaPlan* plan) {
  if (rows.empty()) return;
  for (size_t vertex = 0; vertex < closed.size(); ++vertex) {
    if (!closed[vertex]) continue;
    for (const auto& [area, opening] : model.openings[vertex]) {
      if (OnRow(rows, opening.left) || OnRow(rows, opening.right)) closed[vertex] = false;
    }
  }
  JoinAreasAtFurnitureGaps(graph, model, closed, rows, max_piece_m2, plan);
}

}  // namespace areagraph
