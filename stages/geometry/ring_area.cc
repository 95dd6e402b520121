#include "stages/geometry/ring_area.h"

#include "stages/geometry/ring_points.h"

namespace areagraph {

double TwiceSignedArea(const proto::Ring& ring) {
  double sum = 0;
  const int n = RingSize(ring);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d a = RingPoint(ring, i), b = RingPoint(ring, (i + 1) % n);
    sum += a.x() * b.y() - b.x() * a.y();
  }
  return sum;
}

}  // namespace areagraph
