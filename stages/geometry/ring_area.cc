#include "stages/geometry/ring_area.h"

namespace areagraph {

double TwiceSignedArea(const proto::Ring& ring) {
  double sum = 0;
  const int n = ring.points_size();
  for (int i = 0; i < n; ++i) {
    const proto::Point2& a = ring.points(i);
    const proto::Point2& b = ring.points((i + 1) % n);
    sum += a.x() * b.y() - b.x() * a.y();
  }
  return sum;
}

}  // namespace areagraph
