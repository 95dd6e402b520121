#pragma once

#include <string>

#include "proto/artifacts.pb.h"
#include "stages/geometry/edge_polygon.h"

namespace areagraph {

// Local door decisions (cut.close_wall_doors): sites along the line across
// each door that the width estimate found (EstimateRoomWidth: a narrowing
// between two clearly wider spaces) whose two jambs are the building's wall
// structure, so that the room disk never passes such a door, however wide W
// is. A door's jambs:
// - are the nearest non-free cells on either side of its narrowest point;
// - both lie in obstacle regions that are the building's structure: regions
//   that touch the image border or are at least kMinWallRegionM long (a
//   desk or a shelf standing free is a small island, and its gap to a wall
//   is no door);
// - line up with a wall: past each jamb, away from the door, the line
//   through both jambs runs on in non-free cells for kJambRunM.
// Returns the added sites (pixel coordinates, about one per pixel).
PointList DoorClosingSites(const proto::RoomWidthEstimate& estimate, const std::string& cells,
                           int width, int height, double resolution_m);

// Obstacle regions at least this long (metres, bounding box) are structure.
inline constexpr double kMinWallRegionM = 4.0;
// How far the wall must run on past each jamb along the door's line (m).
inline constexpr double kJambRunM = 0.3;
// Share of the cells along that run that must be non-free.
inline constexpr double kJambRunShare = 0.8;

}  // namespace areagraph
