#include "stages/geometry/ring_points.h"

namespace areagraph {

int RingSize(const proto::Ring& ring) {
  return ring.points_size() > 0 ? ring.points_size() : ring.xy_size() / 2;
}

Eigen::Vector2d RingPoint(const proto::Ring& ring, int i) {
  if (ring.points_size() > 0) return {ring.points(i).x(), ring.points(i).y()};
  return {ring.xy(2 * i), ring.xy(2 * i + 1)};
}

PointList RingPoints(const proto::Ring& ring) {
  const int n = RingSize(ring);
  PointList out;
  out.reserve(n);
  for (int i = 0; i < n; ++i) out.push_back(RingPoint(ring, i));
  return out;
}

void SetPackedRing(const PointList& points, proto::Ring* ring) {
  ring->clear_points();
  google::protobuf::RepeatedField<double>* xy = ring->mutable_xy();
  xy->Clear();
  xy->Reserve(static_cast<int>(2 * points.size()));
  for (const Eigen::Vector2d& point : points) {
    xy->AddAlreadyReserved(point.x());
    xy->AddAlreadyReserved(point.y());
  }
}

}  // namespace areagraph
