#include "stages/cut/cut_graph_builder.h"

#include <cmath>
#include <iterator>
#include <map>
#include <memory>

#include "common/error.h"
#include "stages/common/stage_info.h"
#include "stages/cut/absorbed_polygons.h"
#include "stages/cut/closed_passages.h"
#include "stages/cut/cut_passes.h"
#include "stages/cut/cut_planning.h"
#include "stages/cut/door_sites.h"
#include "stages/cut/edge_track.h"
#include "stages/cut/mouth_sites.h"
#include "stages/cut/narrow_tails.h"
#include "stages/cut/openings.h"
#include "stages/cut/room_disks.h"
#include "stages/cut/room_width.h"
#include "stages/cut/structure_sites.h"
#include "stages/geometry/cell_grid.h"
#include "stages/geometry/obstacle_regions.h"
#include "stages/geometry/obstacle_sites.h"
#include "stages/geometry/polygon_raster.h"
#include "stages/geometry/pool_tasks.h"
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

// Edges per range of WallGapSites' tasks (about 2 M instructions at 8 x 8).
constexpr size_t kGapEdgesPerRange = 32;

// Everything cut needs before its room shape: W, the boundary mask and the
// sites, in rounds of independent tasks on the pool (each writes only its
// own result; the site list is joined in the serial order). The obstacle
// depth and the free-space labels, which the serial steps never held at
// once, are not alive at once here either (the obstacle labels live beside
// each, as before), so the stage's peak memory stays the serial one's.
struct CutInputs {
  proto::RoomWidthEstimate room_width;
  cv::Mat inside;  // BoundaryMask
  PointList sites;
  std::vector<Opening> openings;
  PointList closing;  // the sites that close openings on purpose
};

CutInputs GatherCutInputs(const proto::TopologyGraph& topology, const proto::CleanedMap& map,
                          const proto::CutOptions& options, const CellGrid& grid,
                          const std::function<void()>& between_steps) {
  CutInputs in;
  const int width = grid.width(), height = grid.height();
  const double resolution_m = grid.resolution_m();
  // The narrowest door: the width of the body the map is segmented for.
  const double robot_width_m = map.robot_width_m();
  const double island_max_m = IslandMaxLengthM(options);
  const double gap_max_m = WallGapMaxWidthM(options);
  // Door jambs are the building's structure: obstacles longer than any island.
  const double structure_m = options.islands().max_length_m();
  const double mouth_max_m = MouthMaxWidthM(options);
  const bool closes_doors = RunsCutPass(options, proto::CutOptions::CLOSE_WALL_DOORS);
  const bool islands = island_max_m > 0;
  const bool finds_gaps = gap_max_m > 0;
  const bool closes_lines = closes_doors || finds_gaps || mouth_max_m > 0;
  std::vector<int> site_cells;
  IslandDepth island_depth;
  // The obstacles labelled once for the three site finders.
  ObstacleLabels obstacles;
  // W and the boundary mask on this thread (the mask lives on, and a pool
  // thread's malloc arena would take fresh memory for it), the obstacle
  // depth on the pool; then the site cells and the obstacle labels go to
  // whichever thread is free first (see RunTasks): on a big map the depth
  // takes longest, and the labels, which need nothing else of this round,
  // fill the caller's wait. OpenCV labels serially inside a task (its
  // parallel loops do not nest) but the same labels. ChooseRoomWidth is
  // also the first that may throw.
  RunTasks(
      {
          [&] { in.room_width = ChooseRoomWidth(options, map.frame(), topology, robot_width_m); },
          [&] {
            in.inside = BoundaryMask(topology.part_boundaries(), topology.boundary(),
                                     cv::Size(width, height));
          },
          [&] {
            if (islands) island_depth = IslandDepthOf(map.cells(), width, height, resolution_m);
          },
          [&] { site_cells = ObstacleSiteCells(map.cells(), width, height); },
          [&] {
            if (islands || closes_lines) obstacles = LabelObstacles(map.cells(), width, height);
          },
      },
      /*on_caller=*/2);
  // The estimate's scratch is gone; the rasters below come from new mappings.
  if (between_steps) between_steps();
  in.sites = StructureSitesFrom(site_cells, island_depth, width, resolution_m, island_max_m,
                                options.islands().end_on_face_share(),
                                RunsCutPass(options, proto::CutOptions::WALL_PIECES_NEED_BOTH_ENDS),
                                obstacles);
  island_depth = IslandDepth();
  std::vector<int>().swap(site_cells);
  cv::Mat free_spaces;
  if (closes_lines) {
    free_spaces = LabelFreeSpaces(map.cells(), width, height);
  }
  const cv::Mat* spaces = free_spaces.empty() ? nullptr : &free_spaces;
  // The door sites beside the gap sites' edge ranges.
  std::unique_ptr<WallGapFinder> gap_finder;
  if (finds_gaps) {
    gap_finder =
        std::make_unique<WallGapFinder>(topology, obstacles, resolution_m, structure_m,
                                        robot_width_m, gap_max_m, /*short_tips=*/true, spaces);
  }
  const size_t edge_count = static_cast<size_t>(topology.edges_size());
  const int gap_ranges = gap_finder ? ParallelRangeCount(edge_count, kGapEdgesPerRange) : 0;
  std::vector<std::vector<Opening>> gaps(gap_ranges);
  std::vector<Opening> mouths;
  std::vector<std::function<void()>> tasks = {
      [&] {
        if (closes_doors) {
          in.openings =
              NarrowingOpenings(in.room_width, obstacles, resolution_m, structure_m, spaces);
        }
      },
      [&] {
        mouths =
            MouthOpenings(obstacles, resolution_m, structure_m, robot_width_m, mouth_max_m, spaces);
      }};
  for (int range = 0; range < gap_ranges; ++range) {
    tasks.push_back([&, range] {
      gaps[range] = gap_finder->Openings(
          static_cast<int>(ParallelRangeBegin(edge_count, gap_ranges, range)),
          static_cast<int>(ParallelRangeBegin(edge_count, gap_ranges, range + 1)));
    });
  }
  RunTasks(tasks);
  gaps.push_back(std::move(mouths));
  for (std::vector<Opening>& part : gaps) {
    std::move(part.begin(), part.end(), std::back_inserter(in.openings));
  }
  in.closing = ClosingSites(in.openings);
  in.sites.insert(in.sites.end(), in.closing.begin(), in.closing.end());
  if (in.room_width.automatic() && options.room_width_open_doors()) {
    KeepWidthAboveOpenDoors(in.openings, ClosedLines(in.closing, resolution_m), options,
                            robot_width_m, &in.room_width);
  }
  return in;
}

// One edge cut by its plan into pieces (room ids, ends and ids are set when
// the pieces join the Cut Graph), its absorbed polygons moved to the nearest
// piece. `given`: the edge itself when the caller gave the graph up.
std::vector<proto::GraphEdge> CutEdge(const proto::GraphEdge& edge,
                                      const std::vector<EdgePiece>& plan, proto::GraphEdge* given) {
  const EdgeTrack track(edge);
  // A graph the caller gave up hands its edge over (`edge` is then empty).
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
  for (proto::Polygon& polygon : absorbed) {
    const size_t k = pieces.size() == 1 ? 0 : NearestPiece(pieces, polygon.outer());
    *pieces[k].add_absorbed() = std::move(polygon);
  }
  // Freed as soon as it is read no more: the pieces take the memory.
  if (given != nullptr) proto::GraphEdge().Swap(given);
  return pieces;
}

}  // namespace

proto::CutGraph BuildCutGraph(const proto::TopologyGraph& topology, const proto::CleanedMap& map,
                              const proto::CutOptions& options, proto::TopologyGraph* owned,
                              const std::function<void()>& between_steps) {
  // Cut's working set is a run's largest, and its big rasters come from
  // fresh mappings: what the stages before it freed may go back first.
  if (between_steps) between_steps();
  const CellGrid grid(map);
  CheckTopology(topology);
  if (!map.has_robot_width_m()) {
    throw InputError(
        "the CleanedMap holds no robot width (written by clean 4 or older): run ag-clean again");
  }
  CutInputs in = GatherCutInputs(topology, map, options, grid, between_steps);
  const proto::RoomWidthEstimate& room_width = in.room_width;
  const double room_width_px = room_width.room_width_m() / grid.resolution_m();
  auto inside_boundary = [&](const Eigen::Vector2d& p) {
    const int col = static_cast<int>(std::floor(p.x())), row = static_cast<int>(std::floor(p.y()));
    return grid.Contains(col, row) && in.inside.at<uint8_t>(row, col) != 0;
  };
  const ClosedLines closed_lines(in.closing, grid.resolution_m());
  const ClosedLines* kept_tips =
      RunsCutPass(options, proto::CutOptions::KEEP_CLOSED_ROOM_TIPS) ? &closed_lines : nullptr;
  RoomDisks shape(std::move(in.sites), room_width_px,
                  SmallRoomWidthM(options, room_width, map.robot_width_m()) / grid.resolution_m(),
                  inside_boundary, topology);
  const int room_count = shape.room_count();
  auto room_at = [&](const Eigen::Vector2d& p) { return shape.RoomAt(p); };

  proto::CutGraph out;
  out.set_format_version(kCutGraphFormatVersion);
  *out.mutable_frame() = map.frame();
  *out.mutable_boundary() = topology.boundary();
  *out.mutable_part_boundaries() = topology.part_boundaries();
  out.set_parts(topology.parts());
  out.set_dropped_parts(topology.dropped_parts());
  out.set_dropped_area_m2(topology.dropped_area_m2());
  out.set_min_clearance_m(topology.min_clearance_m());
  out.set_island_max_length_m(options.islands().max_length_m());
  *out.mutable_vertices() = topology.vertices();
  *out.mutable_room_width() = room_width;

  // The plans in edge order: each RoomAt walk starts where the last ended,
  // and a point on a Delaunay edge gets the face its walk stops in.
  const int edge_count = topology.edges_size();
  std::vector<std::vector<EdgePiece>> plans(edge_count);
  // The edges' ends, read before a given edge is emptied.
  std::vector<std::pair<int, int>> ends(edge_count);
  std::map<int, int> room_ids;  // old room id -> kept room id, by first piece
  for (int edge_index = 0; edge_index < edge_count; ++edge_index) {
    const proto::GraphEdge& edge = topology.edges(edge_index);
    const EdgeTrack track(edge);
    ends[edge_index] = {edge.source(), edge.target()};
    const bool source_dead = topology.vertices(edge.source()).kind() == proto::VERTEX_DEAD_END;
    const bool target_dead = topology.vertices(edge.target()).kind() == proto::VERTEX_DEAD_END;
    std::vector<EdgePiece>& plan = plans[edge_index];
    plan = PlanEdgeCuts(track, source_dead, target_dead, room_width_px, room_at, kept_tips);
    if (RunsCutPass(options, proto::CutOptions::CUT_NARROW_TAILS))
      CutNarrowTails(track, source_dead, target_dead, grid.resolution_m(), &plan);
    for (const EdgePiece& piece : plan) {
      if (piece.room >= 0) room_ids.emplace(piece.room, static_cast<int>(room_ids.size()));
    }
  }
  std::vector<int> renumber(room_count, -1);
  for (const auto& [old_id, new_id] : room_ids) renumber[old_id] = new_id;
  shape.RenumberRooms(renumber);

  // The edges' pieces on this thread (see RunTasks) beside the room outlines
  // (the shape is not read by the pieces).
  std::vector<proto::Polygon> outlines;
  std::vector<std::vector<proto::GraphEdge>> cut(edge_count);
  RunTasks({[&] {
              for (int e = 0; e < edge_count; ++e) {
                cut[e] = CutEdge(topology.edges(e), plans[e],
                                 owned != nullptr ? owned->mutable_edges(e) : nullptr);
              }
            },
            [&] { outlines = shape.RoomOutlines(); }},
           /*on_caller=*/1);

  for (int edge_index = 0; edge_index < edge_count; ++edge_index) {
    std::vector<proto::GraphEdge>& pieces = cut[edge_index];
    const std::vector<EdgePiece>& plan = plans[edge_index];
    int from_vertex = ends[edge_index].first;
    for (size_t k = 0; k < pieces.size(); ++k) {
      proto::GraphEdge& piece = pieces[k];
      piece.set_room_id(plan[k].room < 0 ? -1 : room_ids.at(plan[k].room));
      piece.set_source(from_vertex);
      if (k + 1 == pieces.size()) {
        piece.set_target(ends[edge_index].second);
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
    for (proto::GraphEdge& piece : pieces) {
      piece.set_id(out.edges_size());
      *out.add_edges() = std::move(piece);
    }
  }

  outlines.resize(room_ids.size());
  for (proto::Polygon& outline : outlines) *out.add_room_shapes() = std::move(outline);
  MarkClosedPassages(closed_lines, &out);
  AddOpenings(in.openings, &out);
  return out;
}

}  // namespace areagraph
