#pragma once

#include <memory>
#include <string>
#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/cut/openings.h"
#include "stages/cut/width_estimate.h"
#include "stages/geometry/edge_polygon.h"
#include "stages/geometry/obstacle_regions.h"

namespace areagraph {

// The doors that the width estimate found (EstimateRoomWidth: a narrowing
// between two clearly wider spaces) as openings, each closed
// (cut pass CLOSE_WALL_DOORS) when its two jambs are the building's wall
// structure, so that the room disk never passes such a door, however wide
// W is. A door's jambs:
// - are the nearest non-free cells on either side of its narrowest point;
// - both lie in obstacle regions that are the building's structure: regions
//   that touch the image border or are at least `structure_m` long
//   (cut.islands.max_length_m: longer than any island of furniture; a desk or
//   a shelf standing free is a small island, and its gap to a wall is no
//   door);
// - line up with a wall: past each jamb, away from the door, the line
//   through both jambs runs on in non-free cells for kJambRunM.
// `obstacles` labels the map's cells (LabelObstacles). With `free_spaces`
// (LabelFreeSpaces; always, when cut closes anything), the free cells that the
// door's free space cannot reach count as non-free past a jamb: the wall
// behind them is drawn as a thin line (a map whose outside is drawn free) or
// as the outline of a hollow block. Null: only non-free cells count.
std::vector<Opening> NarrowingOpenings(const proto::RoomWidthEstimate& estimate,
                                       const ObstacleLabels& obstacles, double resolution_m,
                                       double structure_m, const cv::Mat* free_spaces = nullptr);
// ClosingSites of NarrowingOpenings.
PointList DoorClosingSites(const proto::RoomWidthEstimate& estimate,
                           const ObstacleLabels& obstacles, double resolution_m, double structure_m,
                           const cv::Mat* free_spaces = nullptr);

// Openings found from the jambs alone, for doors that the width estimate
// misses because the space beyond them does not widen on both sides. Every
// segment of the Topology Graph's edges whose two sites (the nearest
// obstacle cells on its left and right) are at least `min_gap_m` apart
// (clean.robot_width_m: a gap the body does not pass is no door), and
// whose bisector crosses the line between them within the segment, is a
// candidate; both sites must line up with a wall (as above) and one at
// least be wall structure. Consecutive segments of one edge that pass make
// one opening, closed along every segment's line.
// - A wall gap (cut pass CLOSE_WALL_GAPS): at most `max_gap_m` wide, at
//   least one site the end of a thin wall (from the site on, for kJambRunM,
//   the non-free cells across the line span at most kMaxWallThicknessM
//   (stages/geometry/wall_thickness.h), with free
//   cells on both sides), both sites
//   structure, and the free width along the edge growing clearly
//   (IsConstriction's rise) within kDoorReachM on at least one side. A
//   room's cross-section ends in the face of a wall (or of a cabinet
//   standing against one), which is long across the line; a corridor's
//   cross-section between two doors facing each other does not widen on
//   either side. `short_tips` (always in cut): one of the two sites may lie
//   in a region that is not structure when it is the thin wall end and its
//   region is at least kMinWallPieceM long (stages/geometry/furniture_shape.h):
//   a piece of wall between two doors, a partition, a block of a row dividing
//   a room.
// `free_spaces` as for NarrowingOpenings.
PointList WallGapSites(const proto::TopologyGraph& topology, const ObstacleLabels& obstacles,
                       double resolution_m, double structure_m, double min_gap_m, double max_gap_m,
                       bool short_tips, const cv::Mat* free_spaces = nullptr);

// WallGapSites' openings edge range by edge range, for callers that run
// ranges as tasks: the openings of all ranges in edge order are
// WallGapSites'. Reads its arguments, which must outlive it.
class WallGapFinder {
 public:
  WallGapFinder(const proto::TopologyGraph& topology, const ObstacleLabels& obstacles,
                double resolution_m, double structure_m, double min_gap_m, double max_gap_m,
                bool short_tips, const cv::Mat* free_spaces = nullptr);
  ~WallGapFinder();
  // The openings found on edges [begin, end).
  std::vector<Opening> Openings(int begin, int end) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// How far the wall must run on past each jamb along the door's line (m).
inline constexpr double kJambRunM = 0.3;
// Share of the cells along that run that must be non-free.
inline constexpr double kJambRunShare = 0.8;

}  // namespace areagraph
