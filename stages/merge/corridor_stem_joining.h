#pragma once

#include "proto/artifacts.pb.h"
#include "stages/merge/area_assignment.h"
#include "stages/merge/corridor_labels.h"

namespace areagraph {

// The constants of JoinCorridorStems, chosen on the generated tuning and
// tuning-extra floors and the real maps (docs/quality.md, "Options beyond the paper").
struct CorridorStemParams {
  // No narrowing at the stem's mouth: its opening there is at least this
  // share of its own median free width (a closet or a room is wider than
  // its door).
  double opening_share = 0.8;
  // Long and narrow: the stem covers at least this many squares of its
  // median free width, and its major axis' variance is at least
  // `axis_ratio` times its minor axis'.
  double elongation = 3;
  double axis_ratio = 3;
  // The stem is at least this wide (metres): a walkable passage.
  double min_width_m = 0.7;
  // A branch: the stem is at most this share of the corridor's median free
  // width. One about as wide as the corridor (JoinSplitCorridors' width
  // ratio) is a room without a door or the corridor's own end, as wide as
  // the rest (RobotMap lab_c_scan's last office, 2.10 m beside a 2.10 m
  // corridor, lost 0.057 without this).
  double max_width_share = 0.8;
  // The corridor is at most this wide (metres, its median free width; 0: no
  // limit): a wider area is a hall, whose narrow tails cut.cut_narrow_tails
  // made areas of their own (merge.corridor_stems_max_width_m).
  double max_corridor_width_m = kMaxCorridorWidthM;
};

// Joins a room-less dead end (AREA_DEAD_END) into the corridor it opens
// from: every vertex where it meets another area, other than cuts ag-cut
// closed on a door or wall gap (with `keep_closed_doors`), joins it to one
// and the same area, which is a corridor (room-less, or a room shaped like a
// corridor, CorridorLike) clearly wider than the stem; the stem does not
// narrow at its mouth and is long and narrow (the constants above). A
// dead-end branch narrower than W gets no room, and JoinSplitCorridors
// keeps it apart from a corridor more than 1.3 times as wide.
void JoinCorridorStems(const proto::CutGraph& graph, double resolution_m, bool keep_closed_doors,
                       AreaPlan* plan, const CorridorStemParams& params = {});

}  // namespace areagraph
