#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "tools/example_maps/floor_plan.h"

namespace areagraph::floorplan {

// Random numbers that are the same with every standard library (the
// std::*_distribution classes are not): only the mt19937 sequence is used.
class PortableRandom {
 public:
  explicit PortableRandom(uint32_t seed) : engine_(seed) {}
  // Uniform in [low, high).
  double Uniform(double low, double high) {
    return low + (high - low) * (static_cast<double>(engine_()) / 4294967296.0);
  }
  // Uniform integer in [low, high].
  int Int(int low, int high) {
    return low + static_cast<int>(engine_() % static_cast<uint32_t>(high - low + 1));
  }
  bool Chance(double probability) { return Uniform(0, 1) < probability; }

 private:
  std::mt19937 engine_;
};

// What a zone of the ground truth is; furniture depends on it.
enum class ZoneKind {
  kCorridor,
  kRoom,
  kHall,
  kOpenPlan,
  // Public buildings (public_building_layout.h):
  kLobby,        // the entrance hall, with pillars
  kLectureHall,  // rows of seats with aisles
  kStairs,       // a stair core: a room with the stair's middle wall
  kBay,          // a room open to a hall or corridor along a whole side
  kDeadEnd,      // a corridor behind a door that ends blind
};

// The kind a person gives the zone in the ground truth, with the names of
// the Area Graph's kinds: "room", "corridor" or "dead_end".
const char* GroundTruthKindName(ZoneKind kind);
// Corridors and dead ends: furnished like a corridor.
bool IsCorridorKind(ZoneKind kind);

// One zone of the ground truth: a walled region made of overlapping
// rectangles (an L or T corridor has several).
struct Zone {
  ZoneKind kind = ZoneKind::kRoom;
  std::vector<RectM> parts;
};

// A door in the wall between two zones, centred at (x, y) on the wall's
// centre line.
struct DoorM {
  double x = 0;
  double y = 0;
  double width = 0;
  WallDirection wall = WallDirection::kHorizontal;
  // An opening along the whole shared side: `width` is the distance between
  // the centre lines of the two walls that end there, and the drawing opens
  // it up to their faces (width less one wall thickness).
  bool whole_side = false;
};

// A floor in metres before it is drawn (x right, y down, all coordinates at
// least 1 m from the plan's edges).
struct FloorLayout {
  // Which kind of floor: "two-sided corridor", "L corridor", "hall", ...
  std::string name;
  std::vector<Zone> zones;
  std::vector<DoorM> doors;
  // Width of the main corridor, 0 when there is none.
  double corridor_width_m = 0;
  double width_m = 0;
  double height_m = 0;
  // Fixed furniture drawn as obstacles inside zones (seat rows, pillars,
  // the middle wall of a stair), and closed shafts (lifts: walled boxes
  // whose inside stays unknown, in no zone).
  std::vector<RectM> fixtures;
  std::vector<RectM> shafts;
};

// Whether two rectangles overlap by more than a shared wall line (5 cm).
bool RectsOverlap(const RectM& a, const RectM& b);

// A layout being built: zones (and shafts) that must not overlap.
class LayoutCanvas {
 public:
  FloorLayout& layout() { return layout_; }
  // Adds a zone; returns its index.
  int AddZone(ZoneKind kind, std::vector<RectM> parts);
  // Whether `rect` overlaps no zone and no shaft.
  bool Free(const RectM& rect) const;

 protected:
  FloorLayout layout_;
};

// Moves everything so that the drawing starts 1 m from the plan's top-left
// corner, and sets the plan's size.
void FrameLayout(FloorLayout* layout);

// Door, corridor and room sizes of the generated floors (metres).
inline constexpr double kMinDoorM = 0.7;
inline constexpr double kMaxDoorM = 1.4;
inline constexpr double kMinCorridorM = 1.1;
inline constexpr double kMaxCorridorM = 3.0;
inline constexpr double kMinRoomM = 2.0;
inline constexpr double kMaxRoomM = 15.0;

// A random floor: offices on one or two sides of a straight, L or T corridor,
// a corridor with a dead-end branch, or a hall with rooms around it; rooms of
// 2-15 m (a few are halls or open-plan offices), each with a door of 0.7-1.4 m
// to the corridor or hall and some with a door to their neighbour.
FloorLayout RandomFloorLayout(PortableRandom& random);

}  // namespace areagraph::floorplan
