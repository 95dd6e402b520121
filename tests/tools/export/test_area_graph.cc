#include "tests/tools/export/test_area_graph.h"

#include <utility>
#include <vector>

#include "stages/common/map_frame.h"

namespace areagraph::testing {

namespace {

void AddRing(const std::vector<std::pair<double, double>>& corners, const MapTransform& transform,
             proto::Ring* pixels, proto::Ring* metres) {
  for (const auto& [x, y] : corners) {
    proto::Point2* pixel = pixels->add_points();
    pixel->set_x(x);
    pixel->set_y(y);
    const Eigen::Vector2d world = transform.PixelToWorld({x, y});
    proto::Point2* metre = metres->add_points();
    metre->set_x(world.x());
    metre->set_y(world.y());
  }
}

// Corners in pixel order right, down, left; in metres (y up) that ring runs
// clockwise, so exports that want counter-clockwise rings must reverse it.
std::vector<std::pair<double, double>> Square(double x0, double y0, double size) {
  return {{x0, y0}, {x0 + size, y0}, {x0 + size, y0 + size}, {x0, y0 + size}};
}

}  // namespace

proto::AreaGraph TwoRoomAreaGraph() {
  proto::AreaGraph graph;
  graph.set_format_version(1);
  proto::MapFrame* frame = graph.mutable_frame();
  frame->set_resolution_m(0.05);
  frame->set_origin_x_m(1.0);
  frame->set_origin_y_m(2.0);
  frame->set_width_px(40);
  frame->set_height_px(20);
  const MapTransform transform(*frame);

  proto::Area* room = graph.add_areas();
  room->set_id(0);
  room->set_kind(proto::AREA_ROOM);
  room->set_area_m2(0.25);
  AddRing(Square(2, 2, 10), transform, room->mutable_polygon_px()->mutable_outer(),
          room->mutable_polygon_m()->mutable_outer());
  room->add_passage_ids(0);

  proto::Area* corridor = graph.add_areas();
  corridor->set_id(1);
  corridor->set_kind(proto::AREA_CORRIDOR);
  corridor->set_area_m2(0.24);
  AddRing(Square(12, 2, 10), transform, corridor->mutable_polygon_px()->mutable_outer(),
          corridor->mutable_polygon_m()->mutable_outer());
  AddRing(Square(16, 6, 2), transform, corridor->mutable_polygon_px()->add_holes(),
          corridor->mutable_polygon_m()->add_holes());
  corridor->add_passage_ids(0);

  proto::Passage* passage = graph.add_passages();
  passage->set_id(0);
  passage->set_area_a(0);
  passage->set_area_b(1);
  const Eigen::Vector2d a = transform.PixelToWorld({12, 4}), b = transform.PixelToWorld({12, 10});
  passage->mutable_point_m()->set_x((a.x() + b.x()) / 2);
  passage->mutable_point_m()->set_y((a.y() + b.y()) / 2);
  passage->mutable_segment_m()->mutable_a()->set_x(a.x());
  passage->mutable_segment_m()->mutable_a()->set_y(a.y());
  passage->mutable_segment_m()->mutable_b()->set_x(b.x());
  passage->mutable_segment_m()->mutable_b()->set_y(b.y());
  passage->set_width_m(0.3);
  // The shared border x = 12 from y = 4 to 10, through a vertex at y = 7.
  for (const double y : {4.0, 7.0, 10.0}) {
    const Eigen::Vector2d point = transform.PixelToWorld({12, y});
    proto::Point2* border = passage->add_border_m();
    border->set_x(point.x());
    border->set_y(point.y());
  }
  return graph;
}

}  // namespace areagraph::testing
