#include "stages/cut/structure_sites.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/cut/door_sites.h"
#include "stages/geometry/cell_states.h"
#include "stages/geometry/corridor_shape.h"
#include "stages/geometry/furniture_shape.h"
#include "stages/geometry/obstacle_regions.h"
#include "stages/geometry/obstacle_sites.h"
#include "stages/geometry/wall_thickness.h"

namespace areagraph {
namespace {

// The distance (px, in whole steps) along `along` from `end` to the first cell
// of an obstacle other than `region`, at most `gap_px`; -1 when there is none.
double OtherObstacleWithin(const ObstacleRegions& regions, int region, const Eigen::Vector2d& end,
                           const Eigen::Vector2d& along, double gap_px) {
  for (double t = 0; t <= gap_px; t += 1) {
    const int label = regions.LabelAt(end + t * along);
    if (label != 0 && label != region) return t;
  }
  return -1;
}

// Whether, past one end of `region` along its axis (`direction` +1 or -1),
// within `gap_px`, another obstacle continues the region's line end-on for
// `run_px` and is about as wide as the region (at most kCorridorWidthRatio
// times, the shape model's "about as wide", stages/geometry/corridor_shape.h:
// pieces of one wall keep its width as pieces of one corridor do): a wall
// broken by a door, or a row of blocks that divides a room, rather than
// furniture standing free. A desk's line ends in the face of a wall, which
// is long across it.
// The line is probed at `offset` px beside the region's centre line.
bool ContinuedEndOnAt(const ObstacleRegions& regions, int region, int direction, double offset,
                      double gap_px, double run_px) {
  const RegionShape& shape = regions.shapes[region];
  const Eigen::Vector2d along = direction * shape.axis;
  const Eigen::Vector2d across(-along.y(), along.x());
  const Eigen::Vector2d end = shape.centre + 0.5 * shape.length * along + offset * across;
  const double hit = OtherObstacleWithin(regions, region, end, along, gap_px);
  if (hit < 0) return false;
  for (double t = hit; t <= hit + run_px; t += 1) {
    if (!regions.NonFree(end + t * along)) return false;
  }
  // Its extent across the line, halfway along the run, counted both ways.
  const Eigen::Vector2d middle = end + (hit + 0.5 * run_px) * along;
  const double limit = 2 * shape.width;
  double extent = 1;
  for (const int side : {-1, 1}) {
    for (double s = 1; s <= limit && regions.NonFree(middle + side * s * across); s += 1) {
      extent += 1;
    }
  }
  return extent <= kCorridorWidthRatio * shape.width;
}

// ContinuedEndOnAt on the centre line, or on any line across the middle
// `face_share` of the region's end face, one per pixel: a wall piece of a
// row need not be centred on the region's line. Lines near the face's edges
// are left out: there a desk's edge lines up with a cabinet or a door jamb.
bool ContinuedEndOn(const ObstacleRegions& regions, int region, int direction, double gap_px,
                    double run_px, double face_share) {
  if (ContinuedEndOnAt(regions, region, direction, 0, gap_px, run_px)) return true;
  const double half = face_share * (0.5 * regions.shapes[region].width - 1);
  for (double offset = 1; offset <= half; offset += 1) {
    if (ContinuedEndOnAt(regions, region, direction, offset, gap_px, run_px) ||
        ContinuedEndOnAt(regions, region, direction, -offset, gap_px, run_px)) {
      return true;
    }
  }
  return false;
}

// Whether, past the end of `region` in `direction`, another obstacle lies
// within `gap_px` on any line across its end face: the other jamb of a door.
bool ObstacleBeyondEnd(const ObstacleRegions& regions, int region, int direction, double gap_px) {
  const RegionShape& shape = regions.shapes[region];
  const Eigen::Vector2d along = direction * shape.axis;
  const Eigen::Vector2d across(-along.y(), along.x());
  const double half = 0.5 * shape.width - 1;
  for (double offset = -half; offset <= half; offset += 1) {
    const Eigen::Vector2d end = shape.centre + 0.5 * shape.length * along + offset * across;
    if (OtherObstacleWithin(regions, region, end, along, gap_px) >= 0) return true;
  }
  return false;
}

// Whether `region` is a piece of a wall: continued end-on past one end and,
// with `both_ends`, facing another obstacle within a door's width past the
// other end too (a piece of wall stands between two doors).
bool WallPiece(const ObstacleRegions& regions, int region, double gap_px, double run_px,
               double face_share, bool both_ends) {
  for (const int direction : {1, -1}) {
    if (ContinuedEndOn(regions, region, direction, gap_px, run_px, face_share) &&
        (!both_ends || ObstacleBeyondEnd(regions, region, -direction, gap_px))) {
      return true;
    }
  }
  return false;
}

// Regions that may be islands, `candidate` set for them: off the image
// border, and not too long by their box (the rectangle around cells whose
// centres span `extent` px along x or y is at least extent / sqrt 2 long;
// 0.7 leaves a margin for minAreaRect's float sides), with the rectangle and
// thickness (twice the deepest cell of `depth`) of each. The other regions
// keep only their cell count and border flag: no island can come of them, and
// DescribeObstacleRegions' pass over every cell and fits of long walls are
// skipped.
ObstacleRegions CandidateRegions(const ObstacleLabels& obstacles, const cv::Mat& depth,
                                 const std::vector<int>& site_cells, double max_island_px,
                                 std::vector<uint8_t>* candidate) {
  ObstacleRegions regions;
  regions.width = obstacles.labels.cols;
  regions.height = obstacles.labels.rows;
  regions.labels = obstacles.labels;  // shared, read only
  regions.shapes.resize(obstacles.count);
  candidate->assign(obstacles.count, 0);
  for (int region = 1; region < obstacles.count; ++region) {
    const int* stat = obstacles.stats.ptr<int>(region);
    const int left = stat[cv::CC_STAT_LEFT], top = stat[cv::CC_STAT_TOP];
    const int box_width = stat[cv::CC_STAT_WIDTH], box_height = stat[cv::CC_STAT_HEIGHT];
    RegionShape& shape = regions.shapes[region];
    shape.cells = stat[cv::CC_STAT_AREA];
    shape.on_border = left == 0 || top == 0 || left + box_width == regions.width ||
                      top + box_height == regions.height;
    const int extent = std::max(box_width, box_height) - 1;
    (*candidate)[region] = !shape.on_border && 0.7 * extent <= max_island_px;
  }
  const int* label = regions.labels.ptr<int>();
  std::vector<std::vector<cv::Point2f>> outline(obstacles.count);
  for (const int index : site_cells) {
    if ((*candidate)[label[index]]) {
      outline[label[index]].emplace_back(index % regions.width + 0.5f,
                                         index / regions.width + 0.5f);
    }
  }
  for (int region = 1; region < obstacles.count; ++region) {
    if (!(*candidate)[region]) continue;
    RegionShape& shape = regions.shapes[region];
    FitRegionRectangle(outline[region], &shape);
    const int* stat = obstacles.stats.ptr<int>(region);
    for (int r = stat[cv::CC_STAT_TOP]; r < stat[cv::CC_STAT_TOP] + stat[cv::CC_STAT_HEIGHT]; ++r) {
      const int* row_label = regions.labels.ptr<int>(r);
      const float* row_depth = depth.ptr<float>(r);
      for (int c = stat[cv::CC_STAT_LEFT]; c < stat[cv::CC_STAT_LEFT] + stat[cv::CC_STAT_WIDTH];
           ++c) {
        if (row_label[c] == region) shape.thickness = std::max(shape.thickness, 2 * row_depth[c]);
      }
    }
  }
  return regions;
}

}  // namespace

IslandDepth IslandDepthOf(const std::string& cells, int width, int height, double resolution_m) {
  IslandDepth island_depth;
  island_depth.depth = ObstacleDepth(ObstacleMask(cells, width, height));
  island_depth.min_thickness_px =
      std::max(kMinFurnitureThicknessM / resolution_m,
               kFurnitureWallRatio *
                   TypicalWallThickness(island_depth.depth, kMaxWallThicknessM / resolution_m));
  return island_depth;
}

PointList StructureSitesFrom(const std::vector<int>& site_cells, const IslandDepth& island_depth,
                             int width, double resolution_m, double max_island_m,
                             double end_on_face_share, bool wall_piece_both_ends,
                             const ObstacleLabels& obstacles) {
  std::vector<uint8_t> island;
  ObstacleRegions regions;
  if (max_island_m > 0) {
    const double max_island_px = max_island_m / resolution_m;
    const double min_thickness = island_depth.min_thickness_px;
    regions = CandidateRegions(obstacles, island_depth.depth, site_cells, max_island_px, &island);
    const double gap_px = kWallPieceGapM / resolution_m;
    const double run_px = kJambRunM / resolution_m;
    for (size_t region = 1; region < regions.shapes.size(); ++region) {
      if (!island[region]) continue;
      const RegionShape& s = regions.shapes[region];
      island[region] = !s.on_border && s.length <= max_island_px && s.thickness >= min_thickness &&
                       s.length <= kWallPieceElongation * s.width &&
                       s.cells >= kMinFurnitureSolidity * s.length * s.width;
      if (island[region] &&
          WallPiece(regions, region, gap_px, run_px, end_on_face_share, wall_piece_both_ends)) {
        island[region] = 0;
      }
    }
  }
  PointList sites;
  sites.reserve(site_cells.size());
  for (const int index : site_cells) {
    if (!island.empty() && island[regions.labels.ptr<int>()[index]]) continue;
    sites.push_back(CellCentre(index % width, index / width));
  }
  return sites;
}

PointList StructureSites(const std::string& cells, int width, int height, double resolution_m,
                         double max_island_m, double end_on_face_share, bool wall_piece_both_ends,
                         const ObstacleLabels& obstacles) {
  const IslandDepth island_depth =
      max_island_m > 0 ? IslandDepthOf(cells, width, height, resolution_m) : IslandDepth();
  return StructureSitesFrom(ObstacleSiteCells(cells, width, height), island_depth, width,
                            resolution_m, max_island_m, end_on_face_share, wall_piece_both_ends,
                            obstacles);
}

}  // namespace areagraph
