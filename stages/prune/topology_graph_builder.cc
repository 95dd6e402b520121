#include "stages/prune/topology_graph_builder.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <opencv2/imgproc.hpp>
#include <set>
#include <vector>

#include "common/error.h"
#include "common/text.h"
#include "stages/common/pipeline_options_check.h"
#include "stages/common/stage_info.h"
#include "stages/geometry/cell_grid.h"
#include "stages/geometry/parallel_ranges.h"
#include "stages/geometry/region_boxes.h"
#include "stages/geometry/ring_points.h"
#include "stages/geometry/site_alpha_shape.h"
#include "stages/prune/chain_graph.h"
#include "stages/prune/chain_pruning.h"
#include "stages/prune/voronoi_filter.h"

namespace areagraph {
namespace {

// Below this many chains per range ToProto builds the edges' messages in the
// calling thread (a range is a task on OpenCV's pool; each chain's messages
// are a few dozen allocations).
constexpr size_t kMinEdgesPerRange = 64;

std::string Metres(double value) { return FormatNumber(value) + " m"; }

// The 4-connected pieces of the map's free cells: the parts of the map.
struct FreeSpaceParts {
  cv::Mat labels;  // CV_32S; 0 for cells that are not free, else part + 1
  std::vector<int64_t> cells;

  int PartAt(const Eigen::Vector2d& p) const {
    const int col = static_cast<int>(std::floor(p.x())), row = static_cast<int>(std::floor(p.y()));
    if (col < 0 || row < 0 || col >= labels.cols || row >= labels.rows) return -1;
    return labels.at<int>(row, col) - 1;
  }
};

FreeSpaceParts LabelFreeSpace(const CellGrid& grid) {
  cv::Mat free_cells(grid.height(), grid.width(), CV_8U);
  const int width = grid.width();  // a local: the byte stores cannot change it
  for (int r = 0; r < grid.height(); ++r) {
    uint8_t* row = free_cells.ptr<uint8_t>(r);
    const uint8_t* state = grid.CellRow(r);
    for (int c = 0; c < width; ++c) row[c] = state[c] == proto::CELL_FREE ? 1 : 0;
  }
  FreeSpaceParts parts;
  cv::Mat stats;
  const int count = LabelRegionsWithBoxes(free_cells, 4, &parts.labels, &stats);
  for (int label = 1; label < count; ++label) {
    parts.cells.push_back(stats.at<int>(label, cv::CC_STAT_AREA));
  }
  return parts;
}

// The outlines of the enclosed regions that hold a vertex of the kept graph,
// biggest region first (ties: the lower id).
std::vector<proto::Polygon> PartBoundaries(const FilteredGraph& filtered,
                                           const std::vector<double>& region_area) {
  std::set<int> regions;
  for (const ChainEdge& edge : filtered.graph.edges) {
    for (const int v : {edge.source, edge.target}) {
      if (filtered.vertex_region[v] >= 0) regions.insert(filtered.vertex_region[v]);
    }
  }
  std::vector<int> order(regions.begin(), regions.end());
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return region_area[a] > region_area[b]; });
  std::vector<proto::Polygon> outlines;
  for (const int region : order) {
    const proto::Polygon& outline = filtered.region_outlines.at(region);
    if (RingSize(outline.outer()) >= 3) outlines.push_back(outline);
  }
  return outlines;
}

// Takes the graph over: the chains' absorbed polygons move into the proto.
proto::TopologyGraph ToProto(ChainGraph graph, const proto::MapFrame& frame,
                             std::vector<proto::Polygon> parts, const PartSelection& selection,
                             double min_clearance_m) {
  proto::TopologyGraph out;
  out.set_format_version(kTopologyGraphFormatVersion);
  *out.mutable_frame() = frame;
  out.set_min_clearance_m(min_clearance_m);
  if (!parts.empty()) *out.mutable_boundary() = parts.front();
  for (proto::Polygon& part : parts) *out.add_part_boundaries() = std::move(part);
  out.set_parts(selection.kept);
  out.set_dropped_parts(selection.dropped);
  const double resolution = frame.resolution_m();
  out.set_dropped_area_m2(static_cast<double>(selection.dropped_cells) * resolution * resolution);

  const auto incidences = graph.Incidences();
  std::vector<int> new_id(graph.vertices.size(), -1);
  for (size_t v = 0; v < graph.vertices.size(); ++v) {
    if (incidences[v].empty()) continue;
    new_id[v] = out.vertices_size();
    proto::GraphVertex* vertex = out.add_vertices();
    vertex->set_id(new_id[v]);
    *vertex->mutable_position() = ToProtoPoint(graph.vertices[v].position);
    vertex->set_kind(incidences[v].size() == 1 ? proto::VERTEX_DEAD_END : proto::VERTEX_JUNCTION);
    vertex->set_clearance_px(graph.vertices[v].clearance_px);
  }
  // The edges' messages (a heap allocation per point: most of the encoding)
  // are built over ranges of the chains in parallel, and taken over in order.
  std::vector<int> edge_id(graph.edges.size(), -1);
  int kept = 0;
  for (size_t e = 0; e < graph.edges.size(); ++e) {
    if (!graph.edges[e].removed) edge_id[e] = kept++;
  }
  auto built = MapRanges<std::vector<std::unique_ptr<proto::GraphEdge>>>(
      graph.edges.size(), kMinEdgesPerRange, [&](size_t begin, size_t end) {
        std::vector<std::unique_ptr<proto::GraphEdge>> edges;
        for (size_t e = begin; e < end; ++e) {
          ChainEdge& chain = graph.edges[e];
          if (chain.removed) continue;
          proto::GraphEdge* edge = edges.emplace_back(new proto::GraphEdge()).get();
          edge->set_id(edge_id[e]);
          edge->set_source(new_id[chain.source]);
          edge->set_target(new_id[chain.target]);
          AppendPoints(chain.path, edge->mutable_path());
          AppendPoints(chain.left_sites, edge->mutable_left_sites());
          AppendPoints(chain.right_sites, edge->mutable_right_sites());
          for (double c : chain.clearance_px) edge->add_clearance_px(c);
          for (proto::Polygon& polygon : chain.absorbed) *edge->add_absorbed() = std::move(polygon);
          edge->set_length_px(chain.Length());
          edge->set_min_clearance_px(chain.min_clearance_px);
          // UpdateEdgePolygons' rings, from the chain's lists rather than read
          // back out of the messages just written.
          *edge->mutable_left_half()->mutable_outer() =
              HalfPolygonRing(chain.path, chain.left_sites);
          *edge->mutable_right_half()->mutable_outer() =
              HalfPolygonRing(chain.path, chain.right_sites);
          *edge->mutable_polygon()->mutable_outer() =
              EdgePolygonRing(chain.path, chain.left_sites, chain.right_sites);
        }
        return edges;
      });
  out.mutable_edges()->Reserve(kept);
  for (auto& edges : built) {
    for (auto& edge : edges) out.mutable_edges()->AddAllocated(edge.release());
  }
  return out;
}

}  // namespace

proto::TopologyGraph BuildTopologyGraph(const proto::VoronoiDiagram& diagram,
                                        const proto::CleanedMap& map,
                                        const proto::PruneOptions& options,
                                        const std::function<void()>& diagram_done) {
  CheckPruneOptions(options);
  const CellGrid grid(map);
  const double resolution = grid.resolution_m();
  const double map_size_px = std::hypot(grid.width(), grid.height());
  if (options.min_clearance_m() / resolution > map_size_px) {
    throw OptionsError("prune.min_clearance_m = " + Metres(options.min_clearance_m()) +
                       " is larger than the whole map");
  }

  const PlainVoronoi plain = PlainVoronoiOf(diagram);
  if (diagram_done) diagram_done();  // `diagram` may be gone from here on
  if (plain.sites.size() < 3) {
    throw InputError("no Topology Graph: the map has " + std::to_string(plain.sites.size()) +
                     " obstacle cells next to free space, too few to enclose any");
  }
  // Held by pointer: FilteredVoronoiGraph frees it before the chains are
  // built (on large maps it is a good part of the stage's peak memory). The
  // triangulation is the voronoi stage's when this process made the diagram.
  const double alpha_radius_px = options.boundary_alpha_radius_m() / resolution;
  SiteTriangulationPtr voronoi_triangulation = TakeSiteTriangulation(plain.sites);
  std::unique_ptr<SiteAlphaShape> boundary_shape;
  if (voronoi_triangulation != nullptr) {
    boundary_shape =
        std::make_unique<SiteAlphaShape>(std::move(voronoi_triangulation), alpha_radius_px);
  } else {
    boundary_shape = std::make_unique<SiteAlphaShape>(plain.sites, alpha_radius_px);
    boundary_shape->NameVertexFaces(plain.positions);
  }
  const std::vector<double> region_area = boundary_shape->FindEnclosedRegions();
  if (region_area.empty()) {
    throw InputError("no Topology Graph: the obstacles enclose no space (no alpha shape with " +
                     Metres(options.boundary_alpha_radius_m()) + " radius)");
  }

  const double min_clearance_px = options.min_clearance_m() / resolution;
  FilteredGraph filtered =
      FilteredVoronoiGraph(plain, grid, std::move(boundary_shape), min_clearance_px);
  ChainGraph& graph = filtered.graph;
  if (graph.edges.empty()) {
    throw InputError("no Topology Graph: no Voronoi edge inside the boundary keeps " +
                     Metres(options.min_clearance_m()) + " away from obstacles");
  }
  const double dead_end_px = options.dead_end_max_length_m() / resolution;
  for (int pass = 0; pass < options.dead_end_passes(); ++pass) {
    if (RemoveShortDeadEnds(&graph, dead_end_px) == 0) break;
    graph.JoinDegreeTwoChains();
  }
  if (MergeCloseJunctions(&graph) > 0) graph.JoinDegreeTwoChains();
  const FreeSpaceParts free_space = LabelFreeSpace(grid);
  const PartSelection selection = graph.KeepParts(
      [&](int v) { return free_space.PartAt(graph.vertices[v].position); }, free_space.cells,
      static_cast<int64_t>(std::ceil(options.min_component_m2() / (resolution * resolution))),
      options.keep_groups_above_m() / resolution);
  std::vector<proto::Polygon> parts = PartBoundaries(filtered, region_area);
  if (parts.empty()) {
    throw InputError("no Topology Graph: no part of the graph lies inside the boundary");
  }
  return ToProto(std::move(graph), map.frame(), std::move(parts), selection,
                 options.min_clearance_m());
}

}  // namespace areagraph
