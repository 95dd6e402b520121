#include "tools/bench/id_stability.h"

#include <vector>

#include "stages/match/area_cells.h"

namespace areagraph {

GroundTruthView ViewAgainstGroundTruth(const proto::AreaGraph& graph, const cv::Mat& gt_labels,
                                       const cv::Mat& seen) {
  GroundTruthView view;
  // The whole map's frame: the graph's frame grown back to the whole grid.
  proto::MapFrame whole = graph.frame();
  whole.set_origin_x_m(0);
  whole.set_origin_y_m(0);
  whole.set_width_px(gt_labels.cols);
  whole.set_height_px(gt_labels.rows);
  const AreaCells cells = RasterizeAreas(graph, whole);
  std::vector<std::map<int, int64_t>> rooms(graph.areas_size());
  for (int y = 0; y < gt_labels.rows; ++y) {
    for (const CellRun& run : cells.rows[y]) {
      for (int x = run.x0; x < run.x1; ++x) ++rooms[run.area][gt_labels.at<int32_t>(y, x)];
    }
  }
  for (int i = 0; i < graph.areas_size(); ++i) {
    view.ids.insert(graph.areas(i).stable_id());
    int best = 0;
    int64_t best_cells = 0;
    for (const auto& [room, count] : rooms[i]) {
      if (room != 0 && count > best_cells) {
        best = room;
        best_cells = count;
      }
    }
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

IdStability CompareViews(const GroundTruthView& before, const GroundTruthView& after) {
  IdStability stability;
  for (const auto& [id, room] : before.room_of_area) {
    if (before.seen_rooms.count(room) == 0 || after.seen_rooms.count(room) == 0) continue;
    ++stability.tracked;
    const auto now = after.room_of_area.find(id);
    if (now != after.room_of_area.end() && now->second == room) ++stability.kept;
  }
  stability.ids_before = static_cast<int>(before.ids.size());
  for (int id : before.ids) stability.ids_kept += after.ids.count(id) > 0;
  return stability;
}

}  // namespace areagraph
