#pragma once

#include "tools/example_maps/benchmark_layout.h"

namespace areagraph::floorplan {

// Door widths of public buildings (metres): single doors, and double doors
// of seminar rooms, lecture halls, stairs and fire doors in corridors.
inline constexpr double kMinSingleDoorM = 0.8;
inline constexpr double kMaxSingleDoorM = 1.1;
inline constexpr double kMinDoubleDoorM = 1.5;
inline constexpr double kMaxDoubleDoorM = 2.0;
// Corridor widths of the wings: one narrow and one wide wing at least.
inline constexpr double kMinWingCorridorM = 1.5;
inline constexpr double kMaxWingCorridorM = 4.0;

// A random floor of a large public building (a university building, a
// town hall), 100-200 m across: a lobby with pillars in the middle; a wing
// to the left and one to the right, each with its own corridor width
// (1.5-4 m; the corridor opens into the lobby along its whole width or
// through a fire door of 1.5-2 m), and often a third wing above; rooms on
// both sides of each wing corridor (offices with single doors, seminar
// rooms with double doors, small service rooms, stair cores, lift shafts,
// bays open to a wide corridor along their whole side, and a service
// corridor behind a door that ends blind); below the lobby one or two
// lecture halls with rows of seats and aisles, double doors to the aisle
// corridor that runs along them and around their back; around the lobby
// rooms that open to it along a whole side, stairs and lifts.
FloorLayout RandomPublicBuildingLayout(PortableRandom& random);

}  // namespace areagraph::floorplan
