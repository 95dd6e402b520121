#pragma once

#include <utility>
#include <vector>

#include "proto/artifacts.pb.h"

namespace areagraph {

// A point in world metres, compared bit for bit: ring vertices are shared
// exactly between neighbouring areas.
using BorderPoint = std::pair<double, double>;

// Whether p lies on the segment u-v, strictly between its ends (within a
// nanometre of the line).
bool OnSegment(const BorderPoint& p, const BorderPoint& u, const BorderPoint& v);

// `passage` cut where a join's cut (see SplitJoinedAreas) crosses its border
// at `cuts` (points strictly inside its border's edges): the border pieces
// between the cuts, in order along the border, each a passage like
// `passage` with border_m, segment_m and width_m of its own (point_m stays
// where it was for the longest piece and is the middle of the others, which
// have no stable id). Pieces shorter than `min_piece_m` (the robot's width:
// a robot would not pass them) are left out, except the longest. Empty when a cut point
// lies on none of the border's edges.
std::vector<proto::Passage> CutPassage(const proto::Passage& passage,
                                       const std::vector<BorderPoint>& cuts, double min_piece_m);

}  // namespace areagraph
