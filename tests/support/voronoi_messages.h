#pragma once

#include "proto/artifacts.pb.h"

namespace areagraph {

// A diagram of format 2 (arrays) written as format 1 (a message per site,
// vertex and edge, as stores before voronoi 3 hold it): tests read the
// builder's output through the messages, and check that readers take
// either format.
inline proto::VoronoiDiagram VoronoiAsMessages(const proto::VoronoiDiagram& packed) {
  proto::VoronoiDiagram d;
  d.set_format_version(1);
  if (packed.has_frame()) *d.mutable_frame() = packed.frame();
  for (int s = 0; s < packed.site_x_size(); ++s) {
    proto::Point2* site = d.add_sites();
    site->set_x(packed.site_x(s));
    site->set_y(packed.site_y(s));
  }
  for (int v = 0; v < packed.vertex_x_size(); ++v) {
    proto::VoronoiVertex* vertex = d.add_vertices();
    vertex->mutable_position()->set_x(packed.vertex_x(v));
    vertex->mutable_position()->set_y(packed.vertex_y(v));
    vertex->set_clearance_px(packed.vertex_clearance_px(v));
  }
  int ray = 0;
  for (int e = 0; e < packed.edge_source_size(); ++e) {
    proto::VoronoiEdge* edge = d.add_edges();
    edge->set_source(packed.edge_source(e));
    edge->set_target(packed.edge_target(e));
    edge->set_left_site(packed.edge_left_site(e));
    edge->set_right_site(packed.edge_right_site(e));
    edge->set_clearance_px(packed.edge_clearance_px(e));
    if (packed.edge_target(e) < 0) {
      edge->mutable_ray_direction()->set_x(packed.ray_direction_x(ray));
      edge->mutable_ray_direction()->set_y(packed.ray_direction_y(ray));
      ++ray;
    }
  }
  return d;
}

}  // namespace areagraph
