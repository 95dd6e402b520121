#pragma once

#include <cstddef>
#include <vector>

#include "proto/artifacts.pb.h"

namespace areagraph {

// The piece closest to a polygon that a cut edge absorbed (`ring` is its
// outer ring): the first piece, in order, with the least std::hypot between
// a point of its path and a point of `ring`. A dead end's polygon starts at
// the junction where it was removed, which lies on the edge's path, so this
// finds the piece it hung from. 0 when there is no point pair.
size_t NearestPiece(const std::vector<proto::GraphEdge>& pieces, const proto::Ring& ring);

}  // namespace areagraph
