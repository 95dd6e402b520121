#pragma once

#include <string>
#include <vector>

namespace areagraph {

// The colour scale that the viewer uses for clearance (distance from a
// Voronoi or Topology Graph edge to the nearest obstacle), the same for
// every map so that colours can be compared between maps: red where the
// free space is narrow, blue where it is wide, and a faint colour for the
// Voronoi edges that hug obstacles (the bulk of the diagram, not its
// skeleton).
struct ClearanceBand {
  std::string colour;  // CSS colour
  std::string label;   // e.g. "0.25-0.4 m"
};

// Band 0 is "hugs an obstacle" (clearance under 2 px); bands 1.. follow
// kClearanceBandLimitsM.
const std::vector<ClearanceBand>& ClearanceBands();

// The band of a clearance given in pixels, at `resolution_m` per pixel.
int ClearanceBandOf(double clearance_px, double resolution_m);

// Upper limits (metres) of bands 1..N-1; the last band is open.
inline constexpr double kClearanceBandLimitsM[] = {0.15, 0.25, 0.4, 0.6, 0.8, 1.0, 1.5};

// Below this many pixels an edge hugs the obstacles (as in ag-render).
inline constexpr double kHuggingClearancePx = 2.0;

}  // namespace areagraph
