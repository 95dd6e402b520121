#pragma once

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
};

// `graph` (in the frame of a map cropped at `crop` from the whole map, whose
// grid and origin match `gt_labels`) against the ground truth: CV_32S room
// labels of the whole map (0 none), and `seen` (CV_8U, the whole map's cells
// seen so far).
GroundTruthView ViewAgainstGroundTruth(const proto::AreaGraph& graph, const cv::Mat& gt_labels,
                                       const cv::Mat& seen);

// Of the areas of `before` whose room is fully seen in both graphs, how many
// keep their id on an area of the same room in `after`.
struct IdStability {
  int tracked = 0;
  int kept = 0;
  // Of all ids of `before`, how many `after` still has.
  int ids_before = 0;
  int ids_kept = 0;
};
IdStability CompareViews(const GroundTruthView& before, const GroundTruthView& after);

}  // namespace areagraph
