#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/geometry/edge_polygon.h"

namespace areagraph {

// One opening of the map: a narrowing of the free width between two wider
// spaces (a door the width estimate finds), a gap in a wall beside a thin
// wall end, or the mouth of a space whose side walls end on the line of a
// wall (a room or corridor open along its whole width). Cut finds them once
// per map (stages/cut/door_sites.h), decides each from what is around it,
// closes the closed ones for the room disk (ClosingSites) and keeps them in
// the Cut Graph (CutGraph.openings) for the stages after it.
struct Opening {
  proto::Opening::Kind kind = proto::Opening::NARROWING;
  // Where the Topology Graph crosses it (pixels).
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  // Free width (metres).
  double width_m = 0;
  // The obstacle cells on either side (pixels); unset when none was found.
  bool has_jambs = false;
  Eigen::Vector2d jamb_a = Eigen::Vector2d::Zero();
  Eigen::Vector2d jamb_b = Eigen::Vector2d::Zero();
  // The widest free width (metres) within reach on either side along the
  // graph: the two spaces it joins.
  double side_a_m = 0;
  double side_b_m = 0;
  // The decision: the room disk never passes a closed opening.
  bool closed = false;
  // The lines that close it, jamb to jamb (pixels): one, or one per graph
  // segment across a wall gap (they differ by a cell or two).
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> lines;
};

// Sites along the lines of the closed openings, about one per pixel, ends
// excluded: what the room disk meets.
PointList ClosingSites(const std::vector<Opening>& openings);

// The openings as Cut Graph messages.
void AddOpenings(const std::vector<Opening>& openings, proto::CutGraph* graph);

}  // namespace areagraph
