#pragma once

#include <string>
#include <vector>

#include "tools/example_maps/benchmark_layout.h"

namespace areagraph::floorplan {

// How a room is furnished (FurnishRoom draws one of these on purpose).
enum class Furnishing {
  kEmpty,
  kOneDesk,        // one free-standing desk
  kSeveralDesks,   // two to four free-standing desks
  kCabinetByWall,  // one or two cabinets against a wall
  kDeskRing,       // desks against all walls, with gaps between them
  kMixed,          // desks by the walls, a free-standing desk and a cabinet
  kDeskRows,       // open plan: blocks of desks in rows with aisles
};

// The free inside of a zone part: `part` less half the wall thickness on each
// side (walls are centred on the parts' outlines).
RectM InnerRect(const RectM& part, double wall_m);

// Furniture for the free inside `inner` of one room: rectangles (metres) that
// keep `keep_out` clear (the space in front of doors) and keep at least
// kFurnitureGapM from walls and other furniture when free-standing, or touch
// a wall. Trash bins and chairs may come on top with `clutter`.
std::vector<RectM> FurnishRoom(const RectM& inner, Furnishing furnishing,
                               const std::vector<RectM>& keep_out, bool clutter,
                               PortableRandom& random);

// A random furnishing for a zone of `kind` (open-plan zones get desk rows,
// lobbies free-standing desks, bays what halls get; corridors, lecture
// halls and stairs get nothing here).
Furnishing RandomFurnishing(ZoneKind kind, PortableRandom& random);

// A few trash bins and cabinets against the walls of a corridor part at least
// 1.6 m wide, outside `keep_out`.
std::vector<RectM> FurnishCorridor(const RectM& inner, const std::vector<RectM>& keep_out,
                                   PortableRandom& random);

// Free-standing furniture keeps at least this from walls and other furniture:
// more than the 0.3 m gap the Topology Graph needs, so no room is cut off.
inline constexpr double kFurnitureGapM = 0.4;

}  // namespace areagraph::floorplan
