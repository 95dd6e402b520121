#pragma once

#include <Eigen/Core>
#include <vector>

#include "proto/geometry.pb.h"

namespace areagraph {

// Points in pixel coordinates (see proto/geometry.proto).
using PointList = std::vector<Eigen::Vector2d>;

// A ring's points, held as Point2 messages or packed (proto/geometry.proto):
// these read either, so readers need not know which stage wrote the ring.
// Inline: readers call them per point.
inline int RingSize(const proto::Ring& ring) {
  return ring.points_size() > 0 ? ring.points_size() : ring.xy_size() / 2;
}
inline Eigen::Vector2d RingPoint(const proto::Ring& ring, int i) {
  if (ring.points_size() > 0) return {ring.points(i).x(), ring.points(i).y()};
  return {ring.xy(2 * i), ring.xy(2 * i + 1)};
}
PointList RingPoints(const proto::Ring& ring);

// Replaces `ring`'s points by `points`, packed (for the Topology and Cut
// Graphs; the Area Graph keeps Point2 messages, its published format).
void SetPackedRing(const PointList& points, proto::Ring* ring);

}  // namespace areagraph
