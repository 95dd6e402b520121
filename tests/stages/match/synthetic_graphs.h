#pragma once

#include <vector>

#include "proto/artifacts.pb.h"
#include "proto/geometry.pb.h"
#include "proto/pipeline_options.pb.h"

namespace areagraph::testing {

// A rectangle in world metres: [x0, x1] x [y0, y1].
struct WorldRect {
  double x0 = 0;
  double y0 = 0;
  double x1 = 0;
  double y1 = 0;
};

// A frame of width x height px at 0.05 m whose bottom-left corner is at
// (origin_x, origin_y) metres.
proto::MapFrame Frame(int width_px, int height_px, double origin_x = 0, double origin_y = 0);

// An Area Graph (as ag-merge makes it: ids are indices, no stable ids) with
// one rectangular area per rect, in `frame`.
proto::AreaGraph RectGraph(const proto::MapFrame& frame, const std::vector<WorldRect>& rects);

// Adds a passage between areas a and b (indices) at (x, y) metres, 0.9 m wide.
void AddPassage(proto::AreaGraph& graph, int a, int b, double x, double y);

// Rooms A [0,4] and B [4,6] (x, metres), `depth_m` deep, under a corridor C
// 2 m deep, in a 140 px wide frame: passages A-B at (4, depth_m / 2),
// `door_m` wide (none when door_m is 0), then A-C and B-C at the rooms'
// middles. Areas 0, 1, 2, as ag-merge makes them (no stable ids).
proto::AreaGraph TwoRoomsUnderACorridor(double depth_m, double door_m);

// The same floor after ag-merge joined A and B: one room [0,6] and C, with
// both passages to C.
proto::AreaGraph TwoRoomsJoined(double depth_m);

// Expected stable ids, written as Ids{...} in the tests.
using Ids = std::vector<int>;

// The stable ids of the areas in index order, and of the passages.
std::vector<int> AreaIds(const proto::AreaGraph& graph);
std::vector<int> PassageIds(const proto::AreaGraph& graph);

// MatchAreaGraph of `current` after `previous` (null for a first version),
// linked to a made-up predecessor key.
proto::AreaGraph MatchAfter(const proto::AreaGraph& current, const proto::AreaGraph* previous,
                            const proto::MatchOptions& options = {});

}  // namespace areagraph::testing
