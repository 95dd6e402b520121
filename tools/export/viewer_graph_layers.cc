// The viewer's graph layers: Voronoi diagram, Topology Graph, cut graph.
#include <algorithm>
#include <vector>

#include "stages/common/voronoi_arrays.h"
#include "tools/export/clearance_scale.h"
#include "tools/export/svg_path.h"
#include "tools/export/viewer_layers.h"

namespace areagraph {
namespace {

// One path writer per clearance band, turned into the page's buckets
// (empty bands are left out).
class BandPaths {
 public:
  BandPaths() : writers_(ClearanceBands().size()) {}
  SvgPathWriter& operator[](int band) { return writers_[band]; }
  const SvgPathWriter& operator[](int band) const { return writers_[band]; }

  // Band `first` and up; band 0 holds the edges that hug obstacles.
  void AddTo(google::protobuf::RepeatedPtrField<viewer::PathBucket>* buckets,
             size_t first = 0) const {
    for (size_t band = first; band < writers_.size(); ++band) {
      if (!writers_[band].empty()) *buckets->Add() = Bucket(static_cast<int>(band));
    }
  }

  viewer::PathBucket Bucket(int band) const {
    viewer::PathBucket bucket;
    bucket.set_colour(ClearanceBands()[band].colour);
    bucket.set_label(ClearanceBands()[band].label);
    bucket.set_path(writers_[band].text());
    return bucket;
  }

 private:
  std::vector<SvgPathWriter> writers_;
};

// The part of segment a-b inside the map's rectangle (Liang-Barsky), or
// false when none is: the diagram's edges run far out into the unknown
// space around a map, where there is nothing to inspect.
bool ClipToMap(const proto::MapFrame& frame, proto::Point2* a, proto::Point2* b) {
  const double dx = b->x() - a->x(), dy = b->y() - a->y();
  double enter = 0, leave = 1;
  const double p[] = {-dx, dx, -dy, dy};
  const double q[] = {a->x(), frame.width_px() - a->x(), a->y(), frame.height_px() - a->y()};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;  // parallel to this side and outside it
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0) enter = std::max(enter, t);
    if (p[i] > 0) leave = std::min(leave, t);
  }
  if (enter > leave) return false;
  const proto::Point2 from = *a;
  a->set_x(from.x() + enter * dx);
  a->set_y(from.y() + enter * dy);
  b->set_x(from.x() + leave * dx);
  b->set_y(from.y() + leave * dy);
  return true;
}

// Chains the edges of one band into polylines: walks start at vertices where
// an odd number of the band's edges meet (the ends of chains), then at any
// vertex with edges left, and follow unused edges as far as they go. Edges
// are clipped to the map. `voronoi` holds arrays (PackedVoronoi).
void ChainEdges(const proto::VoronoiDiagram& voronoi, const std::vector<int>& edges,
                SvgPathWriter& path) {
  const int vertex_count = voronoi.vertex_x_size();
  std::vector<std::vector<int>> incident(vertex_count);
  for (const int e : edges) {
    incident[voronoi.edge_source(e)].push_back(e);
    incident[voronoi.edge_target(e)].push_back(e);
  }
  auto position = [&](int vertex) {
    proto::Point2 point;
    point.set_x(voronoi.vertex_x(vertex));
    point.set_y(voronoi.vertex_y(vertex));
    return point;
  };
  std::vector<bool> used(voronoi.edge_source_size(), false);
  std::vector<size_t> next(vertex_count, 0);  // first maybe-unused incident edge
  auto take_edge_at = [&](int vertex) -> int {
    while (next[vertex] < incident[vertex].size()) {
      const int e = incident[vertex][next[vertex]++];
      if (!used[e]) return e;
    }
    return -1;
  };
  auto walk_from = [&](int vertex) {
    int e;
    while ((e = take_edge_at(vertex)) >= 0) {
      used[e] = true;
      proto::Point2 from = position(vertex);
      const int source = voronoi.edge_source(e), target = voronoi.edge_target(e);
      vertex = source == vertex ? target : source;
      proto::Point2 to = position(vertex);
      if (!ClipToMap(voronoi.frame(), &from, &to)) continue;
      path.ContinueAt(from.x(), from.y());
      path.LineTo(to.x(), to.y());
    }
  };
  for (int vertex = 0; vertex < vertex_count; ++vertex) {
    if (incident[vertex].size() % 2 == 1) walk_from(vertex);
  }
  for (int vertex = 0; vertex < vertex_count; ++vertex) walk_from(vertex);
}

// An edge for hovering: its path, length and narrowest clearance in metres.
viewer::GraphEdge EdgeOf(const proto::GraphEdge& edge, double resolution_m) {
  viewer::GraphEdge out;
  out.set_id(edge.id());
  out.set_path(PolylinePath(edge.path()));
  out.set_length_m(Rounded(edge.length_px() * resolution_m, 2));
  out.set_min_clearance_m(Rounded(edge.min_clearance_px() * resolution_m, 3));
  if (edge.room_id() >= 0) out.set_room_id(edge.room_id());
  return out;
}

void AddVertices(const google::protobuf::RepeatedPtrField<proto::GraphVertex>& vertices,
                 google::protobuf::RepeatedPtrField<viewer::GraphVertex>* out) {
  for (const proto::GraphVertex& vertex : vertices) {
    viewer::GraphVertex* added = out->Add();
    added->set_x(Rounded(vertex.position().x(), 1));
    added->set_y(Rounded(vertex.position().y(), 1));
    added->set_kind(vertex.kind() == proto::VERTEX_DEAD_END   ? "dead_end"
                    : vertex.kind() == proto::VERTEX_JUNCTION ? "junction"
                                                              : "passage");
  }
}

}  // namespace

viewer::VoronoiLayer VoronoiLayerOf(const proto::VoronoiDiagram& diagram) {
  proto::VoronoiDiagram converted;
  const proto::VoronoiDiagram& voronoi = PackedVoronoi(diagram, &converted);
  const double resolution = voronoi.frame().resolution_m();
  const int vertex_count = voronoi.vertex_x_size();
  std::vector<std::vector<int>> band_edges(ClearanceBands().size());
  for (int e = 0; e < voronoi.edge_source_size(); ++e) {
    const int source = voronoi.edge_source(e), target = voronoi.edge_target(e);
    if (target < 0 || source < 0 || source >= vertex_count || target >= vertex_count) {
      continue;  // rays, and indices a damaged artifact might hold
    }
    band_edges[ClearanceBandOf(voronoi.edge_clearance_px(e), resolution)].push_back(e);
  }
  BandPaths paths;
  for (size_t band = 0; band < band_edges.size(); ++band) {
    ChainEdges(voronoi, band_edges[band], paths[static_cast<int>(band)]);
  }
  viewer::VoronoiLayer layer;
  paths.AddTo(layer.mutable_buckets(), 1);
  if (!paths[0].empty()) *layer.mutable_hugging() = paths.Bucket(0);
  layer.set_vertices(vertex_count);
  layer.set_edges(voronoi.edge_source_size());
  layer.set_sites(voronoi.site_x_size());
  return layer;
}

viewer::TopologyLayer TopologyLayerOf(const proto::TopologyGraph& graph) {
  const double resolution = graph.frame().resolution_m();
  BandPaths paths;
  viewer::TopologyLayer layer;
  for (const proto::GraphEdge& edge : graph.edges()) {
    const bool has_clearance = edge.clearance_px_size() == edge.path_size();
    for (int i = 1; i < edge.path_size(); ++i) {
      const double clearance = has_clearance
                                   ? std::min(edge.clearance_px(i - 1), edge.clearance_px(i))
                                   : edge.min_clearance_px();
      SvgPathWriter& path = paths[ClearanceBandOf(clearance, resolution)];
      path.ContinueAt(edge.path(i - 1).x(), edge.path(i - 1).y());
      path.LineTo(edge.path(i).x(), edge.path(i).y());
    }
    *layer.add_edges() = EdgeOf(edge, resolution);
  }
  paths.AddTo(layer.mutable_clearance_buckets());
  AddVertices(graph.vertices(), layer.mutable_vertices());
  layer.set_boundary(PolygonPath(graph.boundary()));
  return layer;
}

viewer::CutLayer CutLayerOf(const proto::CutGraph& graph) {
  const double resolution = graph.frame().resolution_m();
  viewer::CutLayer layer;
  for (int room = 0; room < graph.room_shapes_size(); ++room) {
    viewer::RoomShape* shape = layer.add_rooms();
    shape->set_id(room);
    shape->set_path(PolygonPath(graph.room_shapes(room)));
  }
  for (const proto::PassagePoint& point : graph.passage_points()) {
    viewer::CutPoint* cut = layer.add_cut_points();
    cut->set_id(point.id());
    cut->set_x(Rounded(point.position().x(), 1));
    cut->set_y(Rounded(point.position().y(), 1));
    cut->set_width_m(Rounded(2 * point.clearance_px() * resolution, 2));
  }
  for (const proto::GraphEdge& edge : graph.edges()) *layer.add_edges() = EdgeOf(edge, resolution);
  return layer;
}

}  // namespace areagraph
