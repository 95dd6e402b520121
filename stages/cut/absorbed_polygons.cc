#include "stages/cut/absorbed_polygons.h"

#include <cmath>
#include <limits>

namespace areagraph {
namespace {

// Above this, a sum of squares cannot belong to a pair whose std::hypot is
// below `distance`: hypot is within an ulp, the sum within a few; 1e-12
// covers both.
double SquareBound(double distance) { return distance * distance * (1 + 1e-12); }

}  // namespace

size_t NearestPiece(const std::vector<proto::GraphEdge>& pieces, const proto::Ring& ring) {
  size_t nearest = 0;
  double best = std::numeric_limits<double>::infinity();
  double bound = best;
  for (size_t k = 0; k < pieces.size(); ++k) {
    for (const proto::Point2& p : pieces[k].path()) {
      for (const proto::Point2& q : ring.points()) {
        const double dx = p.x() - q.x(), dy = p.y() - q.y();
        // Most pairs end here, without the hypot (20 M instructions on lab_e).
        if (dx * dx + dy * dy > bound) continue;
        const double d = std::hypot(dx, dy);
        if (d < best) {
          best = d, nearest = k;
          bound = SquareBound(best);
        }
      }
    }
  }
  return nearest;
}

}  // namespace areagraph
