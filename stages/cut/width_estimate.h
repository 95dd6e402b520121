#pragma once

#include <algorithm>
#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/geometry/door_reach.h"
#include "stages/geometry/same_width.h"

namespace areagraph {

// Doors and corridors read from the clearance along the Topology Graph's
// edges (free width = 2 * clearance - 1 px, since the sites are obstacle cell
// centres):
// - a door is the narrowest point of an edge within kDoorReachM on both
//   sides, where the width grows by at least kDoorRise (absolute and
//   relative) on both sides within that reach, looking past the edge's ends
//   into the edges that meet there: a constriction between wider spaces;
// - a corridor is a stretch of at least kCorridorMinLengthM along one edge
//   whose width stays within SteadyWidthSpreadM of its narrowest
//   point.
// Returns the doors (one per place, widest first) and corridors found, the
// widest door (the 90th percentile, so that one stray wide gap between
// furniture does not decide)
// and the narrowest corridor (the narrowest stretch), and W by the paper's
// rule: door + `door_margin_m` (the paper: 0.1 m) when the door is narrower
// than the corridor (or within kPaperWidthMarginM), else corridor - 0.1 m;
// one of them alone decides when the other is missing; `fallback_m` when
// neither was found. `above_doors`: door + `door_margin_m` whenever a door
// was found. Never below MinRoomWidthM(robot_width_m), `robot_width_m`
// being clean.robot_width_m (the CleanedMap carries it).
proto::RoomWidthEstimate EstimateRoomWidth(const proto::TopologyGraph& topology,
                                           double resolution_m, double robot_width_m,
                                           double fallback_m, bool above_doors = false,
                                           double door_margin_m = 0.1);
// The same from the edges `edges` (indices, in order) of `topology` only.
proto::RoomWidthEstimate EstimateRoomWidth(const proto::TopologyGraph& topology,
                                           const std::vector<int>& edges, double resolution_m,
                                           double robot_width_m, double fallback_m,
                                           bool above_doors, double door_margin_m);

// The widest door that is not a lone outlier: the 90th percentile of
// `widths_widest_first` once there are ten doors or more; 0 for none. (The
// widest width that recurs in a tenth of the doors was tried: it fits maps
// with one standard door width, but misses the wide openings of others; on
// the benchmark it did worse.)
double WidestDoorM(const std::vector<double>& widths_widest_first);

// The rule above: W from the widest door and the narrowest corridor (0 =
// not found), never below MinRoomWidthM(robot_width_m).
double WidthRule(double door_m, double corridor_m, double fallback_m, bool above_doors,
                 double door_margin_m, double robot_width_m);

// The paper's margin: W = door + 0.1 m, or corridor - 0.1 m. Widths closer
// than this count as the same width (the door against the corridor, the
// width along a corridor).
inline constexpr double kPaperWidthMarginM = 0.1;

// How far a width may stray and still be the same steady width (a corridor
// along its length): kPaperWidthMarginM, or kSameWidthShare of `width_m`
// where that is more (FindCorridors' runs).
inline double SteadyWidthSpreadM(double width_m) {
  return std::max(kPaperWidthMarginM, kSameWidthShare * width_m);
}

inline constexpr double kDoorRiseM = 0.25;
inline constexpr double kDoorRiseRatio = 0.25;
inline constexpr double kCorridorMinLengthM = 2.5;

// The least W: the narrowest door, a gap as wide as the body the map is
// segmented for (clean.robot_width_m: a narrower gap is no door, nobody
// passes it), and the paper's margin above it.
constexpr double MinRoomWidthM(double robot_width_m) { return robot_width_m + kPaperWidthMarginM; }

}  // namespace areagraph
