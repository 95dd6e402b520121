#include "tools/example_maps/exploration.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <opencv2/imgproc.hpp>
#include <random>

namespace areagraph::floorplan {
namespace {

// The offsets of a cell's four neighbours.
constexpr int kDx[4] = {1, -1, 0, 0};
constexpr int kDy[4] = {0, 0, 1, -1};

// A uniform number in [0, 1) from the mt19937 sequence (identical on every
// standard library, unlike std::uniform_real_distribution).
double Uniform(std::mt19937& random) { return (random() >> 8) * (1.0 / 16777216.0); }

// Where the robot starts in each 4-connected free region of at least 2 % of
// the free space, largest region first: its most open cell.
std::vector<cv::Point> StartCells(const cv::Mat& truth) {
  const cv::Mat free_mask = truth == kFreeCell;
  cv::Mat labels, stats, centroids;
  const int count = cv::connectedComponentsWithStats(free_mask, labels, stats, centroids, 4);
  const double free_cells = cv::countNonZero(free_mask);
  std::vector<std::pair<int, int>> regions;  // (-cells, label)
  for (int label = 1; label < count; ++label) {
    const int cells = stats.at<int>(label, cv::CC_STAT_AREA);
    if (cells >= 0.02 * free_cells) regions.emplace_back(-cells, label);
  }
  std::sort(regions.begin(), regions.end());
  cv::Mat distance;
  cv::distanceTransform(free_mask, distance, cv::DIST_L2, 3);
  std::vector<cv::Point> starts;
  for (const auto& [cells, label] : regions) {
    cv::Mat in_region = distance.clone();
    in_region.setTo(0, labels != label);
    cv::Point best;
    cv::minMaxLoc(in_region, nullptr, nullptr, nullptr, &best);
    starts.push_back(best);
  }
  return starts;
}

// Whether free cell (x, y) of what is `seen` borders unseen free space.
bool IsFrontier(const cv::Mat& truth, const cv::Mat& seen, int x, int y) {
  for (int k = 0; k < 4; ++k) {
    const int nx = x + kDx[k], ny = y + kDy[k];
    if (nx < 0 || ny < 0 || nx >= truth.cols || ny >= truth.rows) continue;
    if (seen.at<uint8_t>(ny, nx) == 0 && truth.at<uint8_t>(ny, nx) == kFreeCell) return true;
  }
  return false;
}

// The cells from `from` to the nearest frontier cell through seen free space
// (breadth first, 4-connected), `from` excluded; empty when none is left.
std::vector<cv::Point> PathToFrontier(const cv::Mat& truth, const cv::Mat& seen, cv::Point from) {
  const int width = truth.cols;
  std::vector<int> parent(static_cast<size_t>(truth.total()), -2);
  const int start = from.y * width + from.x;
  std::deque<int> queue = {start};
  parent[start] = -1;
  while (!queue.empty()) {
    const int cell = queue.front();
    queue.pop_front();
    const int x = cell % width, y = cell / width;
    if (cell != start && IsFrontier(truth, seen, x, y)) {
      std::vector<cv::Point> path;
      for (int at = cell; parent[at] != -1; at = parent[at])
        path.emplace_back(at % width, at / width);
      std::reverse(path.begin(), path.end());
      return path;
    }
    for (int k = 0; k < 4; ++k) {
      const int nx = x + kDx[k], ny = y + kDy[k];
      if (nx < 0 || ny < 0 || nx >= width || ny >= truth.rows) continue;
      const int next = ny * width + nx;
      if (parent[next] != -2 || seen.at<uint8_t>(ny, nx) == 0 ||
          truth.at<uint8_t>(ny, nx) != kFreeCell) {
        continue;
      }
      parent[next] = cell;
      queue.push_back(next);
    }
  }
  return {};
}

}  // namespace

cv::Mat ClassifyGrey(const cv::Mat& grey) {
  cv::Mat cells(grey.size(), CV_8U, cv::Scalar(kUnknownCell));
  cells.setTo(kFreeCell, grey >= 250);
  cells.setTo(kOccupiedCell, grey <= 100);
  return cells;
}

Exploration::Exploration(const cv::Mat& truth, const ExplorationSettings& settings)
    : truth_(truth.clone()), settings_(settings), seen_(truth.size(), CV_8U, cv::Scalar(0)) {
  const int spacing =
      std::max(1, static_cast<int>(settings_.scan_spacing_m / settings_.resolution_m));
  cv::Mat seen(truth_.size(), CV_8U, cv::Scalar(0));
  // A region the robot cannot drive into (behind a door drawn closed) is
  // explored after the others, as if it were carried there.
  for (cv::Point pose : StartCells(truth_)) {
    Scan(pose, seen);
    poses_.push_back(pose);
    while (true) {
      const std::vector<cv::Point> path = PathToFrontier(truth_, seen, pose);
      if (path.empty()) break;
      for (size_t i = 0; i < path.size(); ++i) {
        if ((i + 1) % spacing != 0 && i + 1 != path.size()) continue;
        Scan(path[i], seen);
        poses_.push_back(path[i]);
      }
      pose = path.back();
    }
  }
}

void Exploration::Scan(cv::Point pose, cv::Mat& seen) const {
  const double range = settings_.range_m / settings_.resolution_m;
  seen.at<uint8_t>(pose) = 255;
  for (int r = 0; r < settings_.rays; ++r) {
    const double angle = 2 * M_PI * r / settings_.rays;
    const double dx = std::cos(angle), dy = std::sin(angle);
    int px = pose.x, py = pose.y;
    for (double t = 0.5; t <= range; t += 0.5) {
      const int x = static_cast<int>(std::floor(pose.x + 0.5 + t * dx));
      const int y = static_cast<int>(std::floor(pose.y + 0.5 + t * dy));
      if (x == px && y == py) continue;
      if (x < 0 || y < 0 || x >= truth_.cols || y >= truth_.rows) break;
      // No seeing through where two walls meet at a corner only.
      if (x != px && y != py && truth_.at<uint8_t>(py, x) == kOccupiedCell &&
          truth_.at<uint8_t>(y, px) == kOccupiedCell) {
        break;
      }
      const uint8_t cell = truth_.at<uint8_t>(y, x);
      if (cell == kUnknownCell) break;
      seen.at<uint8_t>(y, x) = 255;
      if (cell == kOccupiedCell) break;
      px = x;
      py = y;
    }
  }
}

ExplorationMap Exploration::MapAfter(int step, uint32_t noise_seed) {
  const int until = static_cast<int>(
      std::ceil(static_cast<double>(step) * poses_.size() / std::max(1, settings_.steps)));
  for (; scanned_ < std::min(until, scans()); ++scanned_) Scan(poses_[scanned_], seen_);
  return Noisy(noise_seed);
}

ExplorationMap Exploration::MapAgain(uint32_t noise_seed) const { return Noisy(noise_seed); }

ExplorationMap Exploration::Noisy(uint32_t noise_seed) const {
  std::mt19937 random(noise_seed);
  cv::Mat cells(truth_.size(), CV_8U, cv::Scalar(kUnknownCell));
  truth_.copyTo(cells, seen_);
  const cv::Mat clean = cells.clone();
  int64_t free_cells = 0;
  for (int y = 0; y < cells.rows; ++y) {
    for (int x = 0; x < cells.cols; ++x) {
      if (clean.at<uint8_t>(y, x) != kFreeCell) continue;
      ++free_cells;
      bool by_wall = false, by_unknown = false;
      for (int k = 0; k < 4; ++k) {
        const int nx = x + kDx[k], ny = y + kDy[k];
        if (nx < 0 || ny < 0 || nx >= cells.cols || ny >= cells.rows) continue;
        by_wall |= clean.at<uint8_t>(ny, nx) == kOccupiedCell;
        by_unknown |= clean.at<uint8_t>(ny, nx) == kUnknownCell;
      }
      if (by_wall && Uniform(random) < settings_.wall_noise) {
        cells.at<uint8_t>(y, x) = kOccupiedCell;
      } else if (by_unknown && Uniform(random) < settings_.frontier_noise) {
        cells.at<uint8_t>(y, x) = kUnknownCell;
      }
    }
  }
  const double cell_m2 = settings_.resolution_m * settings_.resolution_m;
  const int64_t speckles = std::llround(settings_.speckles_per_m2 * free_cells * cell_m2);
  for (int64_t placed = 0, tries = 0; placed < speckles && tries < 100 * speckles; ++tries) {
    const int x = static_cast<int>(random() % static_cast<uint32_t>(cells.cols));
    const int y = static_cast<int>(random() % static_cast<uint32_t>(cells.rows));
    if (cells.at<uint8_t>(y, x) != kFreeCell) continue;
    cells.at<uint8_t>(y, x) = kOccupiedCell;
    ++placed;
  }
  ExplorationMap map;
  const int margin = static_cast<int>(std::lround(1.0 / settings_.resolution_m));
  cv::Rect seen_box = cv::boundingRect(seen_);
  seen_box.x -= margin;
  seen_box.y -= margin;
  seen_box.width += 2 * margin;
  seen_box.height += 2 * margin;
  map.crop = seen_box & cv::Rect(0, 0, cells.cols, cells.rows);
  map.cells = cells(map.crop).clone();
  map.seen = seen_.clone();
  return map;
}

}  // namespace areagraph::floorplan
