#pragma once

#include <string>
#include <vector>

#include "stages/geometry/edge_polygon.h"
#include "stages/geometry/obstacle_regions.h"

namespace areagraph {

// The obstacle sites (ObstacleSites) that belong to the building's
// structure: every 8-connected region of non-free cells except islands, the
// regions that touch no image border, whose smallest enclosing (rotated)
// rectangle is at most `max_island_m` long, at most kWallPieceElongation
// times as long as wide and at least kMinFurnitureSolidity full
// (stages/geometry/furniture_shape.h), and that are at least
// kMinFurnitureThicknessM and kFurnitureWallRatio times the map's
// typical wall thick (twice the depth of their deepest cell;
// stages/geometry/wall_thickness.h): free-standing desks, tables and shelves
// that furniture removal left, whose line no other obstacle continues
// end-on (ContinuedEndOn in the .cc). A piece of wall between two doors is
// thinner, longer or continued, and stays. The room disk looks
// only at these sites, so that a room stays one room whatever stands in it;
// furniture standing against a wall is part of the wall's region and still
// counts. `max_island_m` <= 0 keeps every site. `end_on_face_share`
// (cut.islands.end_on_face_share; 0 probes the centre line only): the
// other obstacle may continue the region's line on any line across this
// share of its end face's width, centred on the face, not only on its centre
// line. `wall_piece_both_ends` (cut pass WALL_PIECES_NEED_BOTH_ENDS): a region
// continued end-on is a piece of wall only when another obstacle also lies
// within kWallPieceGapM past its other end (a wall piece stands between two
// doors); a cabinet at a wall that lines up with a desk leaves the desk's
// other end open.
// `obstacles` labels `cells` (LabelObstacles; read only when max_island_m > 0).
PointList StructureSites(const std::string& cells, int width, int height, double resolution_m,
                         double max_island_m, double end_on_face_share, bool wall_piece_both_ends,
                         const ObstacleLabels& obstacles);

// StructureSites in steps, for callers that run them beside other work:
// the obstacle depth (ObstacleDepth) and the least island thickness (px)
// from the map's typical wall, needed only when max_island_m > 0 ...
struct IslandDepth {
  cv::Mat depth;
  double min_thickness_px = 0;
};
IslandDepth IslandDepthOf(const std::string& cells, int width, int height, double resolution_m);
// ... and StructureSites from those, `site_cells` (ObstacleSiteCells of the
// cells) and the labels.
PointList StructureSitesFrom(const std::vector<int>& site_cells, const IslandDepth& island_depth,
                             int width, double resolution_m, double max_island_m,
                             double end_on_face_share, bool wall_piece_both_ends,
                             const ObstacleLabels& obstacles);

}  // namespace areagraph
