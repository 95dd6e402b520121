#pragma once

namespace areagraph {

// How far either side of a narrowing (metres) the space must widen for it to
// be a door: past a door's depth and the stub walls beside it. ag-cut finds
// doors and mouths within it (stages/cut/width_estimate.h); ag-merge measures
// the width beside an opening and a bay's mouth within it.
inline constexpr double kDoorReachM = 1.5;

}  // namespace areagraph
