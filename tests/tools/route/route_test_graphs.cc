#include "tests/tools/route/route_test_graphs.h"

namespace areagraph::testing {
namespace {

void FillRing(const XyList& points, proto::Ring* ring) {
  for (const auto& [x, y] : points) {
    proto::Point2* point = ring->add_points();
    point->set_x(x);
    point->set_y(y);
  }
}

}  // namespace

int AddArea(proto::AreaGraph* graph, const XyList& outer, const std::vector<XyList>& holes) {
  proto::Area* area = graph->add_areas();
  area->set_id(graph->areas_size() - 1);
  area->set_stable_id(100 + area->id());
  FillRing(outer, area->mutable_polygon_m()->mutable_outer());
  for (const XyList& hole : holes) FillRing(hole, area->mutable_polygon_m()->add_holes());
  return area->id();
}

void AddPassage(proto::AreaGraph* graph, int area_a, int area_b, const XyList& border) {
  proto::Passage* passage = graph->add_passages();
  passage->set_id(graph->passages_size() - 1);
  passage->set_stable_id(200 + passage->id());
  passage->set_area_a(area_a);
  passage->set_area_b(area_b);
  for (const auto& [x, y] : border) {
    proto::Point2* point = passage->add_border_m();
    point->set_x(x);
    point->set_y(y);
  }
}

proto::AreaGraph TwoRoomsWithDoor() {
  proto::AreaGraph graph;
  const int a = AddArea(&graph, {{0, 0}, {5, 0}, {5, 1.5}, {5, 2.5}, {5, 4}, {0, 4}});
  const int b = AddArea(&graph, {{5, 0}, {10, 0}, {10, 4}, {5, 4}, {5, 2.5}, {5, 1.5}});
  AddPassage(&graph, a, b, {{5, 1.5}, {5, 2.5}});
  return graph;
}

}  // namespace areagraph::testing
