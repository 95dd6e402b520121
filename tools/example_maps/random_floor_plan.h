#pragma once

#include <cstdint>

#include "tools/example_maps/floor_plan.h"

namespace areagraph::floorplan {

// A small office floor that depends only on `seed`: a straight corridor 1.5
// to 2.5 m wide with two to four rooms of random widths on each side, one
// door (0.8 to 1.1 m) per room, some furniture and sensor noise. Used to
// build synthetic collections (ag-make-collection, benchmarks, runner tests).
FloorPlan RandomOfficePlan(uint32_t seed);

// One walled square room `size_px` pixels wide (0.05 m/px) in which
// `percent` of the free cells are single obstacle cells at random: the worst
// case of clutter for the Voronoi-based stages (thousands of tiny areas to
// fold). Used by the speed benchmark and its test.
FloorPlan ClutteredRoomPlan(int size_px, double percent, uint32_t seed);

}  // namespace areagraph::floorplan
