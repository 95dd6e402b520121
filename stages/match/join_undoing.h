#pragma once

#include <vector>

#include "proto/artifacts.pb.h"
#include "proto/pipeline_options.pb.h"
#include "stages/match/area_cells.h"

namespace areagraph {

// A join is cut apart only where the cut is at most this many times as long
// as the opening (passage border or width) the two areas shared before: a
// longer cut means the wall between them went (a real join). The largest of
// 2, 4 and 8 that keeps the constructed wall removal of
// tests/stages/match/growing_maps_test.cc a join (8 does not); on the tuning
// maps (docs/performance.md, "Match's constants") 2, 4 and 8 kept 98.19, 98.32 and 98.47 % of the
// tracked ids.
inline constexpr double kMaxCutPerOpening = 4.0;

// A join to undo: current area `area`, which took the id of previous area
// `kept`, swallowed previous area `previous`.
struct AreaUnjoin {
  int area = 0;
  int previous = 0;
  int kept = 0;
};

// The joins of `current` that ag-merge made of two areas of `previous` that
// were apart: a previous area smaller than `max_m2` whose id no area of
// `current` took (`ids`, see MatchAreaGraph), with `inside_share`
// (MatchOptions.min_overlap) of its cells (`before`: previous's cells on current's
// grid; `overlaps` from CountOverlaps(before, current's cells)) inside one current area that took
// the id of a previous area with a passage to it. `when_id_moved`
// (match pass UNDO_JOINS_WHEN_ID_MOVED) also counts a previous area whose
// id went to another area than the one holding most of it; `without_passage`
// (UNDO_JOINS_WITHOUT_PASSAGE) also a neighbour it shared only a border
// with. At most one per current
// area (the largest). Scan noise moves merge's room joining back and forth
// from one update to the next, and each join cost the smaller area's id.
std::vector<AreaUnjoin> FindUndoableJoins(const proto::AreaGraph& previous,
                                          const std::vector<int>& ids, const AreaCells& before,
                                          const std::vector<AreaOverlap>& overlaps, double max_m2,
                                          double inside_share, bool when_id_moved,
                                          bool without_passage);

// `current` with each join cut apart again along the previous area's border
// (SplitPolygonByGuide): the piece inside the previous area becomes an area
// of its own (the join's kind, no topology edges), the rest keeps the
// area's index and topology edges. Vertices the cut adds to the joined
// area's border are added to the neighbours that share that border, so
// neighbours still share their border vertex for vertex; the joined area's
// passages go to the piece whose ring holds their border, and a new passage
// (where the previous version's passage between the two was, as wide) joins
// the two pieces along their shared border. Where the cut crosses the border
// of a passage to a third area, that passage is cut too (CutPassage): the
// longest stretch keeps it, each other stretch of at least the robot's width
// (AreaGraph.robot_width_m) is a new passage from its piece; with match pass
// UNDO_JOINS_ACROSS_PASSAGES skipped such a join stays. A join whose cut does not give two simple
// pieces, or is longer than kMaxCutPerOpening times the opening the previous passage had, stays as
// it is; the stretches of the cut that run within options.split_joins_wall_margin_m() of the joined
// area's outline (along a wall that noise moved) do not count as its length. `done` (optional)
// counts the joins undone.
proto::AreaGraph SplitJoinedAreas(const proto::AreaGraph& current, const proto::AreaGraph& previous,
                                  const std::vector<AreaUnjoin>& unjoins,
                                  const proto::MatchOptions& options, int* done = nullptr);

}  // namespace areagraph
