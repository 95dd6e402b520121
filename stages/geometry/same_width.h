#pragma once

namespace areagraph {

// Two widths within this share of the wider one are the same width: scan
// noise on a wall takes or adds that much along a corridor (ag-cut's steady
// corridor width), and an opening that close to the free width beside it is
// no narrowing, so no door: the space goes on through it (ag-merge's room
// joining, bay and corridor-piece folding, small closed rooms).
inline constexpr double kSameWidthShare = 0.1;

}  // namespace areagraph
