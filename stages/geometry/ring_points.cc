#include "stages/geometry/ring_points.h"

namespace areagraph {

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
