#include "tests/stages/match/synthetic_graphs.h"

#include <cmath>

#include "stages/common/map_frame.h"
#include "stages/match/area_graph_matching.h"

namespace areagraph::testing {

proto::MapFrame Frame(int width_px, int height_px, double origin_x, double origin_y) {
  proto::MapFrame frame;
  frame.set_resolution_m(0.05);
  frame.set_origin_x_m(origin_x);
  frame.set_origin_y_m(origin_y);
  frame.set_width_px(width_px);
  frame.set_height_px(height_px);
  return frame;
}

proto::AreaGraph RectGraph(const proto::MapFrame& frame, const std::vector<WorldRect>& rects) {
  proto::AreaGraph graph;
  graph.set_format_version(1);
  *graph.mutable_frame() = frame;
  // As ag-merge writes it with the default options.
  graph.set_robot_width_m(proto::CleanOptions().robot_width_m());
  const MapTransform transform(frame);
  for (const WorldRect& rect : rects) {
    proto::Area* area = graph.add_areas();
    area->set_id(graph.areas_size() - 1);
    area->set_area_m2((rect.x1 - rect.x0) * (rect.y1 - rect.y0));
    const double corners[4][2] = {
        {rect.x0, rect.y0}, {rect.x1, rect.y0}, {rect.x1, rect.y1}, {rect.x0, rect.y1}};
    for (const auto& corner : corners) {
      proto::Point2* metres = area->mutable_polygon_m()->mutable_outer()->add_points();
      metres->set_x(corner[0]);
      metres->set_y(corner[1]);
      const Eigen::Vector2d pixel = transform.WorldToPixel({corner[0], corner[1]});
      proto::Point2* pixels = area->mutable_polygon_px()->mutable_outer()->add_points();
      pixels->set_x(pixel.x());
      pixels->set_y(pixel.y());
    }
  }
  return graph;
}

void AddPassage(proto::AreaGraph& graph, int a, int b, double x, double y) {
  proto::Passage* passage = graph.add_passages();
  passage->set_id(graph.passages_size() - 1);
  passage->set_area_a(a);
  passage->set_area_b(b);
  passage->mutable_point_m()->set_x(x);
  passage->mutable_point_m()->set_y(y);
  passage->set_width_m(0.9);
  graph.mutable_areas(a)->add_passage_ids(passage->id());
  graph.mutable_areas(b)->add_passage_ids(passage->id());
}

namespace {

proto::MapFrame TwoRoomsFrame(double depth_m) {
  return Frame(140, static_cast<int>(std::lround((depth_m + 3) / 0.05)));
}

}  // namespace

proto::AreaGraph TwoRoomsUnderACorridor(double depth_m, double door_m) {
  proto::AreaGraph merged =
      RectGraph(TwoRoomsFrame(depth_m),
                {{0, 0, 4, depth_m}, {4, 0, 6, depth_m}, {0, depth_m, 6, depth_m + 2}});
  if (door_m > 0) {
    AddPassage(merged, 0, 1, 4, depth_m / 2);
    merged.mutable_passages(0)->set_width_m(door_m);
  }
  AddPassage(merged, 0, 2, 2, depth_m);
  AddPassage(merged, 1, 2, 5, depth_m);
  return merged;
}

proto::AreaGraph TwoRoomsJoined(double depth_m) {
  proto::AreaGraph merged =
      RectGraph(TwoRoomsFrame(depth_m), {{0, 0, 6, depth_m}, {0, depth_m, 6, depth_m + 2}});
  AddPassage(merged, 0, 1, 2, depth_m);
  AddPassage(merged, 0, 1, 5, depth_m);
  return merged;
}

std::vector<int> AreaIds(const proto::AreaGraph& graph) {
  std::vector<int> ids;
  for (const proto::Area& area : graph.areas()) ids.push_back(area.stable_id());
  return ids;
}

std::vector<int> PassageIds(const proto::AreaGraph& graph) {
  std::vector<int> ids;
  for (const proto::Passage& passage : graph.passages()) ids.push_back(passage.stable_id());
  return ids;
}

proto::AreaGraph MatchAfter(const proto::AreaGraph& current, const proto::AreaGraph* previous,
                            const proto::MatchOptions& options) {
  VersionLink link;
  if (previous != nullptr) link = {"previous-key", previous->version().number() + 1};
  return MatchAreaGraph(current, previous, link, options);
}

}  // namespace areagraph::testing
