#pragma once

#include <functional>

#include "proto/artifacts.pb.h"

namespace areagraph {

// A straight edge along y = 0 from x = 0 to x = 100 with a point every
// 2 px; the walls are `clearance(x)` away on either side.
inline proto::GraphEdge StraightEdge(const std::function<double(double)>& clearance) {
  proto::GraphEdge edge;
  for (int x = 0; x <= 100; x += 2) {
    proto::Point2* p = edge.add_path();
    p->set_x(x);
    p->set_y(0);
    edge.add_clearance_px(clearance(x));
    if (x < 100) {
      const double mid = x + 1;
      proto::Point2* left = edge.add_left_sites();
      left->set_x(mid);
      left->set_y(-clearance(mid));
      proto::Point2* right = edge.add_right_sites();
      right->set_x(mid);
      right->set_y(clearance(mid));
    }
  }
  edge.set_length_px(100);
  return edge;
}

}  // namespace areagraph
