#pragma once

#include <utility>
#include <vector>

#include "proto/artifacts.pb.h"

namespace areagraph::testing {

using XyList = std::vector<std::pair<double, double>>;

// Adds an area with outline `outer` (and `holes`) in metres; returns its index.
int AddArea(proto::AreaGraph* graph, const XyList& outer, const std::vector<XyList>& holes = {});

// Adds a passage between two areas along `border` (vertices of both outlines).
void AddPassage(proto::AreaGraph* graph, int area_a, int area_b, const XyList& border);

// Two 5 x 4 m rooms side by side, A = [0, 5] x [0, 4] and B = [5, 10] x
// [0, 4], with a door in their wall from (5, 1.5) to (5, 2.5).
proto::AreaGraph TwoRoomsWithDoor();

}  // namespace areagraph::testing
