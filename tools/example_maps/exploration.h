#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

namespace areagraph::floorplan {

// Cell classes of the maps an exploration works on (as proto::CellState).
inline constexpr uint8_t kFreeCell = 0;
inline constexpr uint8_t kOccupiedCell = 1;
inline constexpr uint8_t kUnknownCell = 2;

// The cell classes of an 8-bit grey map, with ag-import's default thresholds
// (>= 250 free, <= 100 occupied, unknown between).
cv::Mat ClassifyGrey(const cv::Mat& grey);

// How a simulated robot explores a map and how noisy its map is.
struct ExplorationSettings {
  // Growing maps to hand out: the path is cut into this many equal parts.
  int steps = 20;
  // A 360-degree range sensor: rays per scan and their reach.
  int rays = 720;
  double range_m = 8.0;
  // A scan every this many metres along the path.
  double scan_spacing_m = 1.0;
  double resolution_m = 0.05;
  // Noise, drawn afresh for every map handed out: a free cell next to a wall
  // turns occupied with this probability (walls a cell thicker here and
  // there), a free cell next to unseen space turns unknown with this one
  // (a ragged frontier), and this many one-cell obstacles per square metre
  // of free space appear (spurious returns).
  double wall_noise = 0.05;
  double frontier_noise = 0.2;
  double speckles_per_m2 = 0.02;
  uint32_t seed = 1;
};

// One map of an exploration, as a robot's SLAM would send it.
struct ExplorationMap {
  // Cell classes of the map, cropped to what was seen plus a margin (SLAM
  // maps grow): `crop` is where it lies in the whole map.
  cv::Mat cells;
  cv::Rect crop;
  // Whole-map mask (255) of the cells seen so far, before noise.
  cv::Mat seen;
};

// A frontier-driven exploration of `truth` (cell classes): from the most open
// free cell of the largest free region, the robot repeatedly goes to the
// nearest seen free cell next to unseen free space, scanning along the way,
// until nothing is left to see; then the same in the next largest region
// (of at least 2 % of the free space) that it has not reached, as if it were
// carried there. Rays stop at occupied and at unknown cells (and at diagonal
// gaps between two walls).
class Exploration {
 public:
  Exploration(const cv::Mat& truth, const ExplorationSettings& settings);

  int steps() const { return settings_.steps; }
  // Scans along the whole path.
  int scans() const { return static_cast<int>(poses_.size()); }

  // The map after `step` of steps() parts of the path (1-based, increasing
  // from call to call), with noise seeded by `noise_seed`.
  ExplorationMap MapAfter(int step, uint32_t noise_seed);
  // The map as it is now with other noise: what a robot standing still
  // sends again.
  ExplorationMap MapAgain(uint32_t noise_seed) const;

 private:
  void Scan(cv::Point pose, cv::Mat& seen) const;
  ExplorationMap Noisy(uint32_t noise_seed) const;

  cv::Mat truth_;
  ExplorationSettings settings_;
  std::vector<cv::Point> poses_;
  cv::Mat seen_;  // what MapAfter has revealed so far
  int scanned_ = 0;
};

}  // namespace areagraph::floorplan
