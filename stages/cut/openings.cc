#include "stages/cut/openings.h"

#include <cmath>

namespace areagraph {
namespace {

void SetPoint(const Eigen::Vector2d& p, proto::Point2* point) {
  point->set_x(p.x());
  point->set_y(p.y());
}

}  // namespace

PointList ClosingSites(const std::vector<Opening>& openings) {
  PointList sites;
  for (const Opening& opening : openings) {
    if (!opening.closed) continue;
    for (const auto& [a, b] : opening.lines) {
      const int steps = static_cast<int>(std::ceil((b - a).norm()));
      for (int k = 1; k < steps; ++k) {
        sites.push_back(a + (b - a) * (static_cast<double>(k) / steps));
      }
    }
  }
  return sites;
}

void AddOpenings(const std::vector<Opening>& openings, proto::CutGraph* graph) {
  for (const Opening& opening : openings) {
    proto::Opening* out = graph->add_openings();
    out->set_kind(opening.kind);
    SetPoint(opening.position, out->mutable_position());
    out->set_width_m(opening.width_m);
    if (opening.has_jambs) {
      SetPoint(opening.jamb_a, out->mutable_jamb_a());
      SetPoint(opening.jamb_b, out->mutable_jamb_b());
    }
    out->set_side_a_m(opening.side_a_m);
    out->set_side_b_m(opening.side_b_m);
    out->set_closed(opening.closed);
  }
}

}  // namespace areagraph
