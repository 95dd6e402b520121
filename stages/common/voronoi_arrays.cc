#include "stages/common/voronoi_arrays.h"

#include <string>

#include "common/error.h"

namespace areagraph {
namespace {

// Throws unless the arrays of one kind (`what`) have `expected` entries.
void CheckLength(int size, int expected, const char* what) {
  if (size != expected) {
    throw InputError(std::string("the Voronoi diagram artifact is corrupt: ") + what + " has " +
                     std::to_string(size) + " entries, not " + std::to_string(expected));
  }
}

void CheckLengths(const proto::VoronoiDiagram& d) {
  CheckLength(d.site_y_size(), d.site_x_size(), "site_y");
  CheckLength(d.vertex_y_size(), d.vertex_x_size(), "vertex_y");
  CheckLength(d.vertex_clearance_px_size(), d.vertex_x_size(), "vertex_clearance_px");
  const int edges = d.edge_source_size();
  CheckLength(d.edge_target_size(), edges, "edge_target");
  CheckLength(d.edge_left_site_size(), edges, "edge_left_site");
  CheckLength(d.edge_right_site_size(), edges, "edge_right_site");
  CheckLength(d.edge_clearance_px_size(), edges, "edge_clearance_px");
  int rays = 0;
  for (const int target : d.edge_target()) rays += target < 0;
  CheckLength(d.ray_direction_x_size(), rays, "ray_direction_x");
  CheckLength(d.ray_direction_y_size(), rays, "ray_direction_y");
}

// Format 1's messages as format 2's arrays (frame and version kept).
proto::VoronoiDiagram ConvertMessages(const proto::VoronoiDiagram& old) {
  proto::VoronoiDiagram d;
  d.set_format_version(old.format_version());
  if (old.has_frame()) *d.mutable_frame() = old.frame();
  for (const proto::Point2& site : old.sites()) {
    d.add_site_x(site.x());
    d.add_site_y(site.y());
  }
  for (const proto::VoronoiVertex& vertex : old.vertices()) {
    d.add_vertex_x(vertex.position().x());
    d.add_vertex_y(vertex.position().y());
    d.add_vertex_clearance_px(vertex.clearance_px());
  }
  for (const proto::VoronoiEdge& edge : old.edges()) {
    d.add_edge_source(edge.source());
    d.add_edge_target(edge.target());
    d.add_edge_left_site(edge.left_site());
    d.add_edge_right_site(edge.right_site());
    d.add_edge_clearance_px(edge.clearance_px());
    if (edge.target() < 0) {
      d.add_ray_direction_x(edge.ray_direction().x());
      d.add_ray_direction_y(edge.ray_direction().y());
    }
  }
  return d;
}

}  // namespace

bool HasVoronoiMessages(const proto::VoronoiDiagram& diagram) {
  return diagram.sites_size() > 0 || diagram.vertices_size() > 0 || diagram.edges_size() > 0;
}

const proto::VoronoiDiagram& PackedVoronoi(const proto::VoronoiDiagram& diagram,
                                           proto::VoronoiDiagram* converted) {
  const proto::VoronoiDiagram* packed = &diagram;
  if (HasVoronoiMessages(diagram)) {
    *converted = ConvertMessages(diagram);
    packed = converted;
  }
  CheckLengths(*packed);
  return *packed;
}

}  // namespace areagraph
