#include "tools/render/artifact_drawing.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <string>
#include <utility>
#include <vector>

#include "stages/common/map_frame.h"
#include "stages/common/voronoi_arrays.h"

namespace areagraph {
namespace {

// BGR colours used across pictures, so that a thing looks the same everywhere.
const cv::Scalar kOutlier(40, 40, 230), kFurniture(0, 150, 255), kBoundary(200, 90, 20),
    kPath(90, 40, 20), kDeadEnd(30, 30, 220), kJunction(160, 30, 130), kPassage(0, 170, 0),
    kText(20, 20, 20);

void DrawVertices(const google::protobuf::RepeatedPtrField<proto::GraphVertex>& vertices,
                  Canvas& canvas) {
  for (const proto::GraphVertex& vertex : vertices) {
    const cv::Scalar colour = vertex.kind() == proto::VERTEX_DEAD_END   ? kDeadEnd
                              : vertex.kind() == proto::VERTEX_JUNCTION ? kJunction
                                                                        : kPassage;
    canvas.Dot(vertex.position(), colour, std::max(2, canvas.scale()));
  }
}

void DrawEdges(const google::protobuf::RepeatedPtrField<proto::GraphEdge>& edges, Canvas& canvas,
               bool colour_by_room) {
  for (const proto::GraphEdge& edge : edges) {
    const int colour_id = colour_by_room && edge.room_id() >= 0 ? edge.room_id() : edge.id() + 1000;
    const cv::Scalar colour = DistinctColour(colour_id);
    canvas.Fill(edge.polygon(), colour, 0.45);
    for (const proto::Polygon& absorbed : edge.absorbed()) canvas.Fill(absorbed, colour, 0.45);
    canvas.Outline(edge.polygon().outer(), colour * 0.7, 1);
  }
  for (const proto::GraphEdge& edge : edges) {
    for (int i = 1; i < edge.path_size(); ++i) {
      canvas.Line(edge.path(i - 1), edge.path(i), kPath, 2);
    }
  }
}

// Map metres back to canvas pixels for the AreaGraph's metric fields.
proto::Point2 ToPixel(const MapTransform& transform, const proto::Point2& metres) {
  const Eigen::Vector2d pixel = transform.WorldToPixel({metres.x(), metres.y()});
  proto::Point2 point;
  point.set_x(pixel.x());
  point.set_y(pixel.y());
  return point;
}

// Every part's boundary, or the one boundary of an artifact from before parts.
void DrawBoundaries(const google::protobuf::RepeatedPtrField<proto::Polygon>& parts,
                    const proto::Polygon& boundary, Canvas& canvas) {
  if (parts.empty()) canvas.Outline(boundary.outer(), kBoundary, 2);
  for (const proto::Polygon& part : parts) canvas.Outline(part.outer(), kBoundary, 2);
}

// The id an area is drawn with: its stable id in a graph from ag-match, so
// that an area keeps its colour and label across its map's versions.
int ShownId(const proto::AreaGraph& graph, const proto::Area& area) {
  return graph.has_version() ? area.stable_id() : area.id();
}

}  // namespace

void DrawCleanedMap(const proto::CleanedMap& cleaned, Canvas& canvas) {
  const int width = cleaned.frame().width_px();
  canvas.PaintCells(cleaned.removed_outlier_cells(), width, kOutlier);
  canvas.PaintCells(cleaned.removed_furniture_cells(), width, kFurniture);
  for (const proto::Polygon& shape : cleaned.furniture_shapes()) {
    canvas.Outline(shape.outer(), kFurniture, 1);
  }
}

void DrawVoronoiDiagram(const proto::VoronoiDiagram& diagram, Canvas& canvas) {
  proto::VoronoiDiagram converted;
  const proto::VoronoiDiagram& voronoi = PackedVoronoi(diagram, &converted);
  const auto& clearances = voronoi.edge_clearance_px();
  // Colour by clearance: thin red near obstacles, thick blue in open space.
  double max_clearance = 1;
  for (const double clearance : clearances) max_clearance = std::max(max_clearance, clearance);
  // Segments between vertices that exist (rays, and indices a damaged
  // artifact might hold, are left out).
  const int vertex_count = voronoi.vertex_x_size();
  auto drawn = [&](int e) {
    const int source = voronoi.edge_source(e), target = voronoi.edge_target(e);
    return source >= 0 && target >= 0 && source < vertex_count && target < vertex_count;
  };
  auto at = [&](int vertex) {
    return cv::Point2d(voronoi.vertex_x(vertex), voronoi.vertex_y(vertex));
  };
  // Edges that hug the obstacles are the bulk of the diagram but not its
  // skeleton: drawn first, blended half into the map so that walls show
  // through them, and the medial axis stands out on top. At 1 px per cell
  // the skeleton is 1 px wide too (a 2-px line is a filled polygon with
  // round caps, three times the work).
  std::vector<std::pair<cv::Point2d, cv::Point2d>> faint;
  faint.reserve(voronoi.edge_source_size());  // most edges are faint: no regrowth
  for (int e = 0; e < voronoi.edge_source_size(); ++e) {
    if (!drawn(e) || clearances[e] >= 2.0) continue;
    faint.emplace_back(at(voronoi.edge_source(e)), at(voronoi.edge_target(e)));
  }
  canvas.FaintLines(faint, cv::Scalar(195, 175, 245), 0.5);
  // The skeleton in edge order, each run of edges of one colour in one call
  // (Canvas::Lines): the same picture as a line per edge.
  std::vector<std::pair<cv::Point2d, cv::Point2d>> run;
  int run_step = -1;
  const auto draw_run = [&] {
    // 32 steps of clearance: the picture keeps few enough colours for a
    // palette PNG, and 32 shades are more than the eye tells apart.
    const double t = run_step / 31.0;
    canvas.Lines(run, cv::Scalar(255 * t, 60, 255 * (1 - t)), std::min(2, canvas.scale()));
    run.clear();
  };
  for (int e = 0; e < voronoi.edge_source_size(); ++e) {
    if (!drawn(e) || clearances[e] < 2.0) continue;
    const int step =
        static_cast<int>(std::round(std::min(1.0, clearances[e] / max_clearance) * 31));
    if (step != run_step && !run.empty()) draw_run();
    run_step = step;
    run.emplace_back(at(voronoi.edge_source(e)), at(voronoi.edge_target(e)));
  }
  if (!run.empty()) draw_run();
}

void DrawTopologyGraph(const proto::TopologyGraph& graph, Canvas& canvas) {
  DrawEdges(graph.edges(), canvas, /*colour_by_room=*/false);
  DrawBoundaries(graph.part_boundaries(), graph.boundary(), canvas);
  DrawVertices(graph.vertices(), canvas);
}

void DrawCutGraph(const proto::CutGraph& graph, Canvas& canvas) {
  for (int room = 0; room < graph.room_shapes_size(); ++room) {
    canvas.Outline(graph.room_shapes(room).outer(), DistinctColour(room) * 0.6, 2);
  }
  DrawEdges(graph.edges(), canvas, /*colour_by_room=*/true);
  DrawBoundaries(graph.part_boundaries(), graph.boundary(), canvas);
  DrawVertices(graph.vertices(), canvas);
  for (const proto::PassagePoint& passage : graph.passage_points()) {
    canvas.Dot(passage.position(), kPassage, std::max(3, canvas.scale() + 1));
  }
}

void DrawAreaGraph(const proto::AreaGraph& graph, Canvas& canvas) {
  const MapTransform transform(graph.frame());
  for (const proto::Area& area : graph.areas()) {
    const cv::Scalar colour = DistinctColour(ShownId(graph, area));
    canvas.Fill(area.polygon_px(), colour, 0.55);
    canvas.Outline(area.polygon_px().outer(), colour * 0.55, 1);
  }
  for (const proto::Passage& passage : graph.passages()) {
    // The shared border the passage opens, or the segment across it.
    std::vector<proto::Point2> line(passage.border_m().begin(), passage.border_m().end());
    if (line.size() < 2) line = {passage.segment_m().a(), passage.segment_m().b()};
    for (size_t i = 1; i < line.size(); ++i) {
      canvas.Line(ToPixel(transform, line[i - 1]), ToPixel(transform, line[i]), kPassage, 3);
    }
    canvas.Dot(ToPixel(transform, passage.point_m()), kPassage, std::max(3, canvas.scale() + 1));
  }
  for (const proto::Area& area : graph.areas()) {
    canvas.Label(ToPixel(transform, area.centroid_m()), std::to_string(ShownId(graph, area)),
                 kText);
  }
}

void DrawDetectedWidths(const proto::RoomWidthEstimate& estimate, double resolution_m,
                        Canvas& canvas) {
  const cv::Scalar door_colour(200, 0, 200), corridor_colour(200, 160, 0);  // BGR
  for (const proto::DetectedWidth& corridor : estimate.corridors()) {
    canvas.Dot(corridor.position(), corridor_colour, std::max(3, canvas.scale() + 1));
  }
  for (const proto::DetectedWidth& door : estimate.doors()) {
    const int radius_px = static_cast<int>(door.width_m() / resolution_m / 2 * canvas.scale());
    cv::circle(canvas.image(), canvas.ToCanvas(door.position()), std::max(3, radius_px),
               door_colour, 2, cv::LINE_AA);
  }
}

void DrawArtifact(const google::protobuf::Message& artifact, Canvas& canvas) {
  if (const auto* cleaned = dynamic_cast<const proto::CleanedMap*>(&artifact)) {
    DrawCleanedMap(*cleaned, canvas);
  } else if (const auto* voronoi = dynamic_cast<const proto::VoronoiDiagram*>(&artifact)) {
    DrawVoronoiDiagram(*voronoi, canvas);
  } else if (const auto* topology = dynamic_cast<const proto::TopologyGraph*>(&artifact)) {
    DrawTopologyGraph(*topology, canvas);
  } else if (const auto* cut = dynamic_cast<const proto::CutGraph*>(&artifact)) {
    DrawCutGraph(*cut, canvas);
  } else if (const auto* areas = dynamic_cast<const proto::AreaGraph*>(&artifact)) {
    DrawAreaGraph(*areas, canvas);
  }
}

}  // namespace areagraph
