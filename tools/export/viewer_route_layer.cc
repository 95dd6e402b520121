#include "tools/export/viewer_route_layer.h"

#include <algorithm>
#include <set>
#include <utility>

#include "common/error.h"
#include "stages/common/map_frame.h"
#include "tools/export/svg_path.h"
#include "tools/route/area_router.h"

namespace areagraph {
namespace {

// Hundredths of a pixel: half a millimetre on a 5 cm map.
constexpr int kDecimals = 2;

void AddPixel(const MapTransform& transform, const Vec2& metres,
              google::protobuf::RepeatedField<double>* out) {
  const Eigen::Vector2d pixel = transform.WorldToPixel(metres);
  out->Add(Rounded(pixel.x(), kDecimals));
  out->Add(Rounded(pixel.y(), kDecimals));
}

}  // namespace

void SetRouteGraph(const proto::AreaGraph& graph, viewer::Run* run) {
  run->clear_route_graph();
  if (!(graph.frame().resolution_m() > 0)) return;
  std::unique_ptr<AreaRouter> router;
  try {
    router = std::make_unique<AreaRouter>(graph);
  } catch (const InputError&) {
    return;
  }
  const MapTransform transform(graph.frame());
  viewer::RouteGraph* out = run->mutable_route_graph();
  for (int c = 0; c < router->corner_count(); ++c) {
    const AreaRouter::Corner& corner = router->corner(c);
    AddPixel(transform, corner.at, out->mutable_corners());
    out->add_corner_kinds(corner.reflex ? 2 : corner.walled ? 1 : 0);
    for (const Vec2& wall : {corner.wall_a, corner.wall_b}) {
      const Eigen::Vector2d direction =
          (transform.WorldToPixel(corner.at + wall) - transform.WorldToPixel(corner.at))
              .normalized();
      out->add_corner_walls(Rounded(direction.x(), 6));
      out->add_corner_walls(Rounded(direction.y(), 6));
    }
  }
  for (const auto& [u, v] : router->Links()) {
    out->add_links(u);
    out->add_links(v);
  }
  const FreeSpace& space = router->free_space();
  for (int area = 0; area < space.area_count(); ++area) {
    viewer::RouteArea* route_area = out->add_areas();
    for (const std::vector<Vec2>& ring : space.area_rings(area)) {
      viewer::RouteRing* route_ring = route_area->add_rings();
      for (const Vec2& point : ring) AddPixel(transform, point, route_ring->mutable_xy());
    }
    for (const int corner : router->EndCandidates(area)) route_area->add_corners(corner);
  }
  // A wall between two areas is an edge of both: sent once.
  std::set<std::pair<int, int>> sent;
  for (const OutlineEdge& edge : space.edges()) {
    if (!edge.wall) continue;
    if (!sent.insert(std::minmax(edge.vertex_a, edge.vertex_b)).second) continue;
    AddPixel(transform, edge.a, out->mutable_walls());
    AddPixel(transform, edge.b, out->mutable_walls());
  }
}

}  // namespace areagraph
