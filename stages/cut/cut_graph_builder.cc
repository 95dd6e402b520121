#include "stages/cut/cut_graph_builder.h"

#include <cmath>
#include <map>

#include "common/error.h"
#include "stages/common/freed_memory.h"
#include "stages/common/stage_info.h"
#include "stages/cut/absorbed_polygons.h"
#include "stages/cut/closed_passages.h"
#include "stages/cut/cut_planning.h"
#include "stages/cut/door_sites.h"
#include "stages/cut/edge_track.h"
#include "stages/cut/narrow_tails.h"
#include "stages/cut/room_width.h"
#include "stages/cut/structure_sites.h"
#include "stages/geometry/cell_grid.h"
#include "stages/geometry/polygon_raster.h"
#include "stages/geometry/site_alpha_shape.h"

namespace areagraph {
namespace {

void CheckTopology(const proto::TopologyGraph& topology) {
  const int vertex_count = topology.vertices_size();
  for (const proto::GraphEdge& edge : topology.edges()) {
    if (edge.source() < 0 || edge.source() >= vertex_count || edge.target() < 0 ||
        edge.target() >= vertex_count) {
      throw InputError("the Topology Graph artifact is corrupt: edge " + std::to_string(edge.id()) +
                       " names a vertex that does not exist");
    }
  }
  if (topology.edges_size() == 0) {
    throw InputError("the Topology Graph has no edges; run ag-prune again");
  }
}

// A room must at least hold the disk of diameter W; smaller ones are slivers
// where a corridor about W wide bulges a little.
void DropSmallRooms(double room_width_px, SiteAlphaShape* shape, int* room_count) {
  const double min_area = M_PI * room_width_px * room_width_px / 4;
  const std::vector<double> areas = shape->RoomAreas();
  std::vector<int> renumber(*room_count, -1);
  int kept = 0;
  for (int room = 0; room < *room_count; ++room) {
    if (room < static_cast<int>(areas.size()) && areas[room] >= min_area) renumber[room] = kept++;
  }
  shape->RenumberRooms(renumber);
  *room_count = kept;
}

}  // namespace

proto::CutGraph BuildCutGraph(const proto::TopologyGraph& topology, const proto::CleanedMap& map,
                              const proto::CutOptions& options, proto::TopologyGraph* owned) {
  const CellGrid grid(map);
  CheckTopology(topology);
  const proto::RoomWidthEstimate room_width = ChooseRoomWidth(options, map.frame(), topology);
  const double room_width_px = room_width.room_width_m() / grid.resolution_m();
  // The estimate's rasters are gone; the obstacle rasters below come from
  // new mappings, so on a big map its freed pages would add to this stage's peak.
  ReturnFreedMemory();

  const cv::Mat inside = BoundaryMask(topology.part_boundaries(), topology.boundary(),
                                      cv::Size(grid.width(), grid.height()));
  auto inside_boundary = [&](const Eigen::Vector2d& p) {
    const int col = static_cast<int>(std::floor(p.x())), row = static_cast<int>(std::floor(p.y()));
    return grid.Contains(col, row) && inside.at<uint8_t>(row, col) != 0;
  };
  // The obstacles labelled once for the three site finders.
  const bool closes_lines = options.close_wall_doors() || options.close_wall_gaps_max_m() > 0;
  ObstacleLabels obstacles;
  if (options.room_island_max_m() > 0 || closes_lines) {
    obstacles = LabelObstacles(map.cells(), grid.width(), grid.height());
  }
  PointList sites = StructureSites(
      map.cells(), grid.width(), grid.height(), grid.resolution_m(), options.room_island_max_m(),
      options.island_end_on_face() ? options.island_end_on_face_share() : 0,
      options.island_wall_piece_both_ends(), obstacles);
  PointList closing;  // the sites that close doors and wall gaps on purpose
  cv::Mat free_spaces;
  if (options.jamb_wall_behind_line() && closes_lines) {
    free_spaces = LabelFreeSpaces(map.cells(), grid.width(), grid.height());
  }
  const cv::Mat* spaces = free_spaces.empty() ? nullptr : &free_spaces;
  if (options.close_wall_doors()) {
    closing = DoorClosingSites(room_width, obstacles, grid.resolution_m(), spaces);
  }
  if (options.close_wall_gaps_max_m() > 0) {
    const PointList gaps =
        WallGapSites(topology, obstacles, grid.resolution_m(), options.close_wall_gaps_max_m(),
                     options.close_wall_gaps_short_tips(), spaces);
    closing.insert(closing.end(), gaps.begin(), gaps.end());
  }
  obstacles = ObstacleLabels();
  free_spaces.release();
  sites.insert(sites.end(), closing.begin(), closing.end());
  const ClosedLines closed_lines(closing, grid.resolution_m());
  const ClosedLines* kept_tips = options.keep_closed_room_tips() ? &closed_lines : nullptr;
  SiteAlphaShape shape(std::move(sites), room_width_px / 2);
  int room_count = shape.DetectRooms(inside_boundary);
  DropSmallRooms(room_width_px, &shape, &room_count);
  auto room_at = [&](const Eigen::Vector2d& p) { return shape.RoomAt(p); };

  proto::CutGraph out;
  out.set_format_version(kCutGraphFormatVersion);
  *out.mutable_frame() = map.frame();
  *out.mutable_boundary() = topology.boundary();
  *out.mutable_part_boundaries() = topology.part_boundaries();
  out.set_parts(topology.parts());
  out.set_dropped_parts(topology.dropped_parts());
  out.set_dropped_area_m2(topology.dropped_area_m2());
  *out.mutable_vertices() = topology.vertices();
  *out.mutable_room_width() = room_width;

  std::map<int, int> room_ids;  // old room id -> kept room id
  auto keep_room = [&](int room) {
    if (room < 0) return -1;
    auto [it, added] = room_ids.emplace(room, static_cast<int>(room_ids.size()));
    return it->second;
  };

  for (int edge_index = 0; edge_index < topology.edges_size(); ++edge_index) {
    const proto::GraphEdge& edge = topology.edges(edge_index);
    const int source = edge.source(), target = edge.target();
    const EdgeTrack track(edge);
    const bool source_dead = topology.vertices(source).kind() == proto::VERTEX_DEAD_END;
    const bool target_dead = topology.vertices(target).kind() == proto::VERTEX_DEAD_END;
    std::vector<EdgePiece> plan =
        PlanEdgeCuts(track, source_dead, target_dead, room_width_px, room_at, kept_tips);
    if (options.cut_narrow_tails()) CutNarrowTails(track, source_dead, target_dead, &plan);

    // The edge's absorbed polygons, and its pieces without them. A graph
    // the caller gave up hands its edge over (`edge` is then empty).
    proto::GraphEdge* given = owned != nullptr ? owned->mutable_edges(edge_index) : nullptr;
    google::protobuf::RepeatedPtrField<proto::Polygon> absorbed;
    if (given != nullptr) {
      absorbed.Swap(given->mutable_absorbed());
    } else {
      absorbed = edge.absorbed();
    }
    std::vector<proto::GraphEdge> pieces;
    if (plan.size() == 1) {
      if (given != nullptr) {
        pieces.push_back(std::move(*given));
      } else {
        pieces.push_back(edge);
        pieces.back().clear_absorbed();
      }
    } else {
      for (const EdgePiece& piece : plan) pieces.push_back(track.Piece(piece.begin, piece.end));
    }
    int from_vertex = source;
    for (size_t k = 0; k < pieces.size(); ++k) {
      proto::GraphEdge& piece = pieces[k];
      piece.set_room_id(keep_room(plan[k].room));
      piece.set_source(from_vertex);
      if (k + 1 == pieces.size()) {
        piece.set_target(target);
        break;
      }
      // A cut: a new passage vertex between this piece and the next.
      proto::GraphVertex* vertex = out.add_vertices();
      vertex->set_id(out.vertices_size() - 1);
      *vertex->mutable_position() = piece.path(piece.path_size() - 1);
      vertex->set_kind(proto::VERTEX_PASSAGE);
      vertex->set_clearance_px(piece.clearance_px(piece.clearance_px_size() - 1));
      proto::PassagePoint* passage = out.add_passage_points();
      passage->set_id(out.passage_points_size() - 1);
      *passage->mutable_position() = vertex->position();
      passage->set_vertex(vertex->id());
      passage->set_clearance_px(vertex->clearance_px());
      piece.set_target(vertex->id());
      from_vertex = vertex->id();
    }
    for (proto::Polygon& polygon : absorbed) {
      const size_t k = pieces.size() == 1 ? 0 : NearestPiece(pieces, polygon.outer());
      *pieces[k].add_absorbed() = std::move(polygon);
    }
    for (proto::GraphEdge& piece : pieces) {
      piece.set_id(out.edges_size());
      *out.add_edges() = std::move(piece);
    }
    // Freed as soon as it is read no more: the pieces take the memory.
    if (given != nullptr) proto::GraphEdge().Swap(given);
  }

  std::vector<int> renumber(room_count, -1);
  for (const auto& [old_id, new_id] : room_ids) renumber[old_id] = new_id;
  shape.RenumberRooms(renumber);
  std::vector<proto::Polygon> outlines = shape.RoomOutlines();
  outlines.resize(room_ids.size());
  for (proto::Polygon& outline : outlines) *out.add_room_shapes() = std::move(outline);
  MarkClosedPassages(closed_lines, &out);
  return out;
}

}  // namespace areagraph
