#pragma once

#include <Eigen/Core>

#include "stages/geometry/cell_grid.h"

namespace areagraph {

// A narrowing is one-sided when the wall behind one of its two sides is flat
// along the passage: all but kMissedWallShare (a scanned wall face has a few
// missing cells; stages/geometry/wall_thickness.h) of the points on the line
// through that side's obstacle cell, across the narrowing's line and reaching
// the narrowing's width past it both ways, are a wall face (an obstacle cell
// there with free cells just in front of it). A door has two jambs, wall
// ends whose wall runs along the door's line, so neither side is such a
// face; a cabinet or a wall's end standing out into a corridor narrows it
// from one side while the corridor's other wall runs on straight.
//
// Whether the narrowing between the obstacle cells `left` and `right`
// (pixel positions, the sites beside it) has a flat wall face on at least one
// side.
bool OneSidedNarrowing(const CellGrid& grid, const Eigen::Vector2d& left,
                       const Eigen::Vector2d& right);

}  // namespace areagraph
