#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "stages/cut/openings.h"
#include "stages/geometry/obstacle_regions.h"

namespace areagraph {

// The mouths of the map (cut pass CLOSE_MOUTHS, cut.mouths.max_width_m): rooms open along a whole
// side to the space in front of them (a bay on a wide corridor, a room open
// to a lobby), each as a closed opening from jamb to jamb. A mouth runs from
// a jamb along a straight wall line across free cells to the first obstacle
// cell, at least `min_mouth_m` (clean.robot_width_m) and at most
// `max_mouth_m` wide, along a grid axis
// (the finder reads the map's rows and columns). Both jambs are the
// building's wall structure (regions at least `structure_m` long, as for
// NarrowingOpenings); the wall line runs on past both (kJambRunM) and
// past one of them for at least two thin walls' thickness (2 x
// kMaxWallThicknessM, stages/geometry/wall_thickness.h), so a cross-section of a corridor between
// two doors, whose walls are thin, is none; at both jambs a side wall leaves the line on the same
// side for kDoorReachM, the wall line being at most kMaxWallThicknessM thick on the other side; and
// the space behind, on the side walls' side, is no corridor (CorridorBehind). `free_spaces` as for
// NarrowingOpenings (stages/cut/door_sites.h).
std::vector<Opening> MouthOpenings(const ObstacleLabels& obstacles, double resolution_m,
                                   double structure_m, double min_mouth_m, double max_mouth_m,
                                   const cv::Mat* free_spaces = nullptr);

}  // namespace areagraph
