#include "stages/cut/room_width.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "common/error.h"
#include "common/text.h"
#include "stages/common/pipeline_options_check.h"
#include "stages/cut/cut_passes.h"
#include "stages/cut/width_estimate.h"
#include "stages/geometry/disjoint_sets.h"

namespace areagraph {
namespace {

void CheckFitsMap(double width, const proto::MapFrame& frame) {
  const double map_width_m = frame.width_px() * frame.resolution_m();
  const double map_height_m = frame.height_px() * frame.resolution_m();
  if (width > std::max(map_width_m, map_height_m)) {
    throw OptionsError("the room width W = " + FormatNumber(width) + " m is wider than the map (" +
                       FormatNumber(map_width_m) + " x " + FormatNumber(map_height_m) + " m)");
  }
}

// The edges (indices, in order) of the graph's connected part with the most
// edge length: the one part of the paper, and the one W is estimated from.
// Smaller parts (a room seen through a window, the fans of free cells that
// laser rays leave outside an incomplete scan) would otherwise shift the
// door estimate, and with it every room of the main part. Indices, not a
// copy of the graph: its edges carry their polygons.
std::vector<int> LongestPart(const proto::TopologyGraph& topology) {
  DisjointSets parts(topology.vertices_size());
  for (const proto::GraphEdge& edge : topology.edges()) parts.Union(edge.source(), edge.target());
  std::vector<double> length(topology.vertices_size(), 0.0);
  for (const proto::GraphEdge& edge : topology.edges()) {
    length[parts.Find(edge.source())] += edge.length_px();
  }
  std::vector<int> part;
  if (length.empty()) {
    for (int e = 0; e < topology.edges_size(); ++e) part.push_back(e);
    return part;
  }
  const int longest =
      static_cast<int>(std::max_element(length.begin(), length.end()) - length.begin());
  for (int e = 0; e < topology.edges_size(); ++e) {
    if (parts.Find(topology.edges(e).source()) == longest) part.push_back(e);
  }
  return part;
}

}  // namespace

double RoomWidthM(const proto::CutOptions& options, const proto::MapFrame& frame) {
  CheckCutOptions(options);
  const double door = options.door_width_m();
  const double corridor = options.corridor_width_m();
  double width = options.room_width_m() > 0 ? options.room_width_m() : kPaperRoomWidthM;
  if (door > 0 && corridor > 0) {
    width = door < corridor ? door + kPaperWidthMarginM : corridor - kPaperWidthMarginM;
  }
  CheckFitsMap(width, frame);
  return width;
}

proto::RoomWidthEstimate ChooseRoomWidth(const proto::CutOptions& options,
                                         const proto::MapFrame& frame,
                                         const proto::TopologyGraph& topology,
                                         double robot_width_m) {
  const double fixed = RoomWidthM(options, frame);
  const bool strategy = options.door_width_m() > 0 && options.corridor_width_m() > 0;
  proto::RoomWidthEstimate estimate;
  if (EstimatesRoomWidth(options) && !strategy) {
    estimate = EstimateRoomWidth(
        topology, LongestPart(topology), frame.resolution_m(), robot_width_m, fixed,
        RunsCutPass(options, proto::CutOptions::WIDTH_ABOVE_DOORS), kPaperWidthMarginM);
    CheckFitsMap(estimate.room_width_m(), frame);
  } else {
    estimate.set_room_width_m(fixed);
    estimate.set_automatic(false);
  }
  return estimate;
}

void KeepWidthAboveOpenDoors(const std::vector<Opening>& openings, const ClosedLines& closed,
                             const proto::CutOptions& options, double robot_width_m,
                             proto::RoomWidthEstimate* estimate) {
  std::vector<double> open;  // widest first, as the estimate's doors
  for (const Opening& opening : openings) {
    if (opening.kind != proto::Opening::NARROWING || opening.closed) continue;
    if (closed.Near(opening.position)) continue;
    open.push_back(opening.width_m);
  }
  if (!RunsCutPass(options, proto::CutOptions::CLOSE_WALL_DOORS)) {
    for (const proto::DetectedWidth& door : estimate->doors()) open.push_back(door.width_m());
  }
  const double door = WidestDoorM(open);
  estimate->set_widest_open_door_m(door);
  const double corridor = estimate->narrowest_corridor_m();
  double width = WidthRule(door, corridor, kPaperRoomWidthM,
                           RunsCutPass(options, proto::CutOptions::WIDTH_ABOVE_DOORS),
                           kPaperWidthMarginM, robot_width_m);
  if (corridor > 0) width = std::max(width, corridor + kPaperWidthMarginM);
  estimate->set_room_width_m(std::min(estimate->room_width_m(), width));
}

}  // namespace areagraph
