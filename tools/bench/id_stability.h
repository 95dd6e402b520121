#pragma once

#include <cstdint>
#include <map>
#include <opencv2/core.hpp>
#include <set>

#include "proto/artifacts.pb.h"

namespace areagraph {

// What the areas of one published graph cover of the ground truth.
struct GroundTruthView {
  // Stable id -> the ground-truth room holding most of the area's cells, for
  // areas with at least half of their cells in one room.
  std::map<int, int> room_of_area;
  // The rooms that are fully seen: at least 98 % of their cells.
  std::set<int> seen_rooms;
  // Every stable id of the graph.
  std::set<int> ids;
  // Stable id -> how the area's cells fall on the ground truth: its largest
  // room, that room's cells, the cells of any room, and all its cells (for
  // saying why an id counts as lost).
  struct RoomShare {
    int room = 0;
    int64_t room_cells = 0;
    int64_t labelled_cells = 0;
    int64_t cells = 0;
  };
  std::map<int, RoomShare> share_of_area;
  // The stable id of the area holding each cell of the whole map (CV_32S, -1
  // for none), and the ground-truth rooms it was scored on (shared, not
  // copied): what CompareViews compares cell by cell.
  cv::Mat id_cells;
  cv::Mat rooms;
};

// `graph` (in the frame of a map cropped at `crop` from the whole map, whose
// grid and origin match `gt_labels`) against the ground truth: CV_32S room
// labels of the whole map (0 none), and `seen` (CV_8U, the whole map's cells
// seen so far).
GroundTruthView ViewAgainstGroundTruth(const proto::AreaGraph& graph, const cv::Mat& gt_labels,
                                       const cv::Mat& seen);

// The id stability of one update, or summed over several. An area of
// `before` is tracked when its room (room_of_area) is fully seen in both
// graphs: the issue's "areas whose ground-truth room is fully revealed and
// unchanged". It kept its id when `after` still has the id on the area that
// holds the most of the cells the area had in that room (ties count): the
// id still names the same place, and a split that keeps the id on its
// largest part keeps it. `kept_same_room` counts the earlier test (until
// 2026-12-02): the id's area must still have at least half of all its cells
// in that room, which counts an area at 50 % in its room as lost whenever
// noise tips it under, and an area that keeps its id while merge joins a
// piece of newly seen corridor to it as lost as well as the piece it
// swallowed; it also let an id move to another area of the same room
// (docs/performance.md, "Live updates and stable ids").
struct IdStability {
  int tracked = 0;
  int kept = 0;
  int kept_same_room = 0;
  // Of all ids of `before`, how many `after` still has.
  int ids_before = 0;
  int ids_kept = 0;
  // The tracked ids that were not kept (one update's; += leaves it).
  std::set<int> lost;

  // Adds the counts of `other`.
  IdStability& operator+=(const IdStability& other);
};
IdStability CompareViews(const GroundTruthView& before, const GroundTruthView& after);

}  // namespace areagraph
