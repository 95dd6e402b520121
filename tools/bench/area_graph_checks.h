#pragma once

#include <utility>
#include <vector>

#include "proto/artifacts.pb.h"

namespace areagraph {

// Pairs (by index in graph.areas, first < second) of areas whose polygons'
// interiors overlap, decided exactly (CGAL's regularized Boolean set
// operations on exact numbers), so that areas that only share a border or a
// corner do not count.
std::vector<std::pair<int, int>> OverlappingAreaPairs(const proto::AreaGraph& graph);

// Whether both end points of the passage's segment_m are, bit for bit,
// vertices of the polygon_m rings (outer or hole) of both its areas.
bool PassageEndsOnBothOutlines(const proto::AreaGraph& graph, const proto::Passage& passage);

}  // namespace areagraph
