#pragma once

#include <cstdint>

#include "tools/example_maps/floor_plan.h"

namespace areagraph::floorplan {

// A small office floor that depends only on `seed`: a straight corridor 1.5
// to 2.5 m wide with two to four rooms of random widths on each side, one
// door (0.8 to 1.1 m) per room, some furniture and sensor noise. Used to
// build synthetic collections (ag-make-collection, benchmarks, runner tests).
FloorPlan RandomOfficePlan(uint32_t seed);

// A large office floor of about width_m x height_m that depends only on
// `seed`: a 2 m corridor down the left side with 2 m corridors branching off
// it every 12 m, lined on both sides with rooms 3 to 7 m wide and 5 m deep,
// one door (0.8 to 1.1 m) per room, a desk in most of them and sensor noise.
// `rooms_closed`, when given, gets the same plan without the doors and with
// walls where the branches leave the spine: its 4-connected free regions are
// the rooms and corridors (the ground truth).
FloorPlan LargeOfficePlan(double width_m, double height_m, uint32_t seed,
                          FloorPlan* rooms_closed = nullptr);

}  // namespace areagraph::floorplan
