#include "stages/cut/mouth_sites.h"

#include <cmath>

#include "stages/cut/door_sites.h"
#include "stages/cut/wall_probes.h"
#include "stages/cut/width_estimate.h"
#include "stages/geometry/wall_thickness.h"

namespace areagraph {

std::vector<Opening> MouthOpenings(const ObstacleLabels& obstacles, double resolution_m,
                                   double structure_m, double min_mouth_m, double max_mouth_m,
                                   const cv::Mat* free_spaces) {
  std::vector<Opening> mouths;
  if (max_mouth_m <= 0) return mouths;
  const WallStructure walls(obstacles, structure_m / resolution_m, free_spaces);
  const double run_px = kJambRunM / resolution_m;
  const double long_run_px = 2 * kMaxWallThicknessM / resolution_m;
  const double depth_px = kDoorReachM / resolution_m;
  const double max_thickness_px = kMaxWallThicknessM / resolution_m;
  const double min_px = min_mouth_m / resolution_m + 1, max_px = max_mouth_m / resolution_m + 1;
  const int width = obstacles.labels.cols, height = obstacles.labels.rows;
  // Each mouth once, from its jamb with the smaller coordinate.
  const Eigen::Vector2d axes[] = {{1, 0}, {0, 1}};
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) {
      if (!walls.IsStructure(walls.LabelAt(col, row))) continue;
      const Eigen::Vector2d a(col + 0.5, row + 0.5);
      for (const Eigen::Vector2d& along : axes) {
        if (walls.LabelAt(a + along) != 0 || walls.LabelAt(a - along) == 0) continue;
        const int space = walls.SpaceAt(a + along);
        const int side = SideWallAt(walls, a, -along, depth_px, max_thickness_px, space);
        if (side == 0 || !WallRunsOn(walls, a, -along, run_px, space)) continue;
        double span = 1;
        while (span <= max_px && walls.LabelAt(a + span * along) == 0) span += 1;
        if (span > max_px || span < min_px) continue;
        const Eigen::Vector2d b = a + span * along;
        if (!walls.IsStructure(walls.LabelAt(b)) || !WallRunsOn(walls, b, along, run_px, space) ||
            SideWallAt(walls, b, along, depth_px, max_thickness_px, space) != -side) {
          continue;
        }
        if (!WallRunsOn(walls, a, -along, long_run_px, space) &&
            !WallRunsOn(walls, b, along, long_run_px, space)) {
          continue;
        }
        // SideWallAt's left normal of jamb a's outward direction (-along).
        const Eigen::Vector2d behind = side * Eigen::Vector2d(along.y(), -along.x());
        if (CorridorBehind(walls, a, b, behind, space)) continue;
        Opening& mouth = mouths.emplace_back();
        mouth.kind = proto::Opening::MOUTH;
        mouth.position = 0.5 * (a + b);
        mouth.width_m = (span - 1) * resolution_m;
        mouth.has_jambs = true;
        mouth.jamb_a = a, mouth.jamb_b = b;
        mouth.closed = true;
        mouth.lines = {{a, b}};
      }
    }
  }
  // The cells of one wall end give parallel lines a cell apart: one opening.
  std::vector<Opening> merged;
  for (Opening& mouth : mouths) {
    bool joined = false;
    for (Opening& kept : merged) {
      const Eigen::Vector2d kept_along = kept.jamb_b - kept.jamb_a;
      const Eigen::Vector2d mouth_along = mouth.jamb_b - mouth.jamb_a;
      const bool parallel = (kept_along.x() == 0) == (mouth_along.x() == 0);
      if (parallel && (kept.position - mouth.position).norm() <= max_thickness_px + 1) {
        kept.lines.push_back(mouth.lines.front());
        joined = true;
        break;
      }
    }
    if (!joined) merged.push_back(std::move(mouth));
  }
  return merged;
}

}  // namespace areagraph
