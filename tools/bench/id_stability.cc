#include "tools/bench/id_stability.h"

#include <vector>

#include "stages/match/area_cells.h"

namespace areagraph {
namespace {

// Stable id -> how the cells its area had in its room lie in `after`
// (stable id there, or -1 for none -> cells), for the tracked areas of
// `before`.
std::map<int, std::map<int, int64_t>> WhereCellsWent(const GroundTruthView& before,
                                                     const GroundTruthView& after) {
  std::map<int, int> tracked;  // stable id -> room
  for (const auto& [id, room] : before.room_of_area) {
    if (before.seen_rooms.count(room) > 0 && after.seen_rooms.count(room) > 0) tracked[id] = room;
  }
  std::map<int, std::map<int, int64_t>> went;
  for (const auto& [id, room] : tracked) went[id];
  if (tracked.empty()) return went;
  for (int y = 0; y < before.id_cells.rows; ++y) {
    const int32_t* was = before.id_cells.ptr<int32_t>(y);
    const int32_t* is = after.id_cells.ptr<int32_t>(y);
    const int32_t* room = before.rooms.ptr<int32_t>(y);
    for (int x = 0; x < before.id_cells.cols; ++x) {
      if (was[x] < 0) continue;
      const auto found = tracked.find(was[x]);
      if (found == tracked.end() || found->second != room[x]) continue;
      ++went[was[x]][is[x]];
    }
  }
  return went;
}

// Whether id holds at least as many of `cells` as any other area.
bool HoldsMost(int id, const std::map<int, int64_t>& cells) {
  const auto own = cells.find(id);
  if (own == cells.end()) return false;
  for (const auto& [other, count] : cells) {
    if (other >= 0 && count > own->second) return false;
  }
  return true;
}

}  // namespace

GroundTruthView ViewAgainstGroundTruth(const proto::AreaGraph& graph, const cv::Mat& gt_labels,
                                       const cv::Mat& seen) {
  GroundTruthView view;
  view.rooms = gt_labels;
  view.id_cells = cv::Mat(gt_labels.size(), CV_32S, cv::Scalar(-1));
  // The whole map's frame: the graph's frame grown back to the whole grid.
  proto::MapFrame whole = graph.frame();
  whole.set_origin_x_m(0);
  whole.set_origin_y_m(0);
  whole.set_width_px(gt_labels.cols);
  whole.set_height_px(gt_labels.rows);
  const AreaCells cells = RasterizeAreas(graph, whole);
  std::vector<std::map<int, int64_t>> rooms(graph.areas_size());
  for (int y = 0; y < gt_labels.rows; ++y) {
    int32_t* ids = view.id_cells.ptr<int32_t>(y);
    for (const CellRun& run : cells.rows[y]) {
      const int id = graph.areas(run.area).stable_id();
      for (int x = run.x0; x < run.x1; ++x) {
        ++rooms[run.area][gt_labels.at<int32_t>(y, x)];
        ids[x] = id;
      }
    }
  }
  for (int i = 0; i < graph.areas_size(); ++i) {
    view.ids.insert(graph.areas(i).stable_id());
    int best = 0;
    int64_t best_cells = 0, labelled = 0;
    for (const auto& [room, count] : rooms[i]) {
      if (room != 0) labelled += count;
      if (room != 0 && count > best_cells) {
        best = room;
        best_cells = count;
      }
    }
    view.share_of_area[graph.areas(i).stable_id()] = {best, best_cells, labelled, cells.cells[i]};
    if (best != 0 && 2 * best_cells >= cells.cells[i]) {
      view.room_of_area[graph.areas(i).stable_id()] = best;
    }
  }
  std::map<int, std::pair<int64_t, int64_t>> room_seen;  // room -> (seen, all)
  for (int y = 0; y < gt_labels.rows; ++y) {
    for (int x = 0; x < gt_labels.cols; ++x) {
      const int room = gt_labels.at<int32_t>(y, x);
      if (room == 0) continue;
      auto& counts = room_seen[room];
      counts.first += seen.at<uint8_t>(y, x) != 0;
      ++counts.second;
    }
  }
  for (const auto& [room, counts] : room_seen) {
    if (counts.first >= 0.98 * counts.second) view.seen_rooms.insert(room);
  }
  return view;
}

IdStability& IdStability::operator+=(const IdStability& other) {
  tracked += other.tracked;
  kept += other.kept;
  kept_same_room += other.kept_same_room;
  ids_before += other.ids_before;
  ids_kept += other.ids_kept;
  return *this;
}

IdStability CompareViews(const GroundTruthView& before, const GroundTruthView& after) {
  IdStability stability;
  for (const auto& [id, cells] : WhereCellsWent(before, after)) {
    ++stability.tracked;
    if (HoldsMost(id, cells)) {
      ++stability.kept;
    } else {
      stability.lost.insert(id);
    }
    const auto now = after.room_of_area.find(id);
    stability.kept_same_room +=
        now != after.room_of_area.end() && now->second == before.room_of_area.at(id);
  }
  stability.ids_before = static_cast<int>(before.ids.size());
  for (int id : before.ids) stability.ids_kept += after.ids.count(id) > 0;
  return stability;
}

}  // namespace areagraph
