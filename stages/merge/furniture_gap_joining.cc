#include "stages/merge/furniture_gap_joining.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "stages/geometry/disjoint_sets.h"
#include "stages/geometry/edge_polygon.h"
#include "stages/geometry/ring_simplicity.h"

namespace areagraph {
namespace {

// The cells whose island values OnIsland reads: the cell under a site (a
// cell centre) and its 8 neighbours, row by row.
void AddCellsAround(const Eigen::Vector2d& site, std::vector<cv::Point>* cells) {
  const int col = static_cast<int>(std::floor(site.x()));
  const int row = static_cast<int>(std::floor(site.y()));
  for (int dr = -1; dr <= 1; ++dr) {
    for (int dc = -1; dc <= 1; ++dc) cells->emplace_back(col + dc, row + dr);
  }
}

bool RowMajor(const cv::Point& a, const cv::Point& b) { return a.y != b.y ? a.y < b.y : a.x < b.x; }

// Island values at the cells a search asked for (sorted row-major, each once).
struct IslandValues {
  std::vector<cv::Point> cells;
  std::vector<uint8_t> values;

  int At(const cv::Point& cell) const {
    const auto it = std::lower_bound(cells.begin(), cells.end(), cell, RowMajor);
    return it != cells.end() && *it == cell ? values[it - cells.begin()] : 0;
  }
};

// Whether the cell under a site, or one of its 8 neighbours, belongs to an
// island.
bool OnIsland(const IslandValues& islands, const Eigen::Vector2d& site) {
  const int col = static_cast<int>(std::floor(site.x()));
  const int row = static_cast<int>(std::floor(site.y()));
  for (int dr = -1; dr <= 1; ++dr) {
    for (int dc = -1; dc <= 1; ++dc) {
      if (islands.At(cv::Point(col + dc, row + dr)) != 0) return true;
    }
  }
  return false;
}

// Folds every group of `groups` into its lowest area; a group with a room
// becomes that room.
void ApplyGroups(DisjointSets& groups, AreaPlan* plan) {
  const int area_count = static_cast<int>(plan->areas.size());
  std::map<int, int> room_of_group;
  for (int k = 0; k < area_count; ++k) {
    if (plan->areas[k].kind == proto::AREA_ROOM) room_of_group.emplace(groups.Find(k), k);
  }
  for (int k = 0; k < area_count; ++k) {
    const auto it = room_of_group.find(groups.Find(k));
    if (it == room_of_group.end()) continue;
    plan->areas[k].kind = proto::AREA_ROOM;
    plan->areas[k].room_id = plan->areas[it->second].room_id;
  }
  std::vector<int> root(area_count);
  for (int k = 0; k < area_count; ++k) root[k] = groups.Find(k);
  plan->MergeGroups(root);
}

}  // namespace

void JoinAreasAtFurnitureGaps(const proto::CutGraph& graph, const PlanModel& model,
                              const std::vector<bool>& closed, const cv::Mat& islands,
                              double max_piece_m2, AreaPlan* plan) {
  const cv::Rect inside(0, 0, islands.cols, islands.rows);
  const IslandsAt from_raster = [&](const std::vector<cv::Point>& cells) {
    std::vector<uint8_t> values(cells.size(), 0);
    for (size_t i = 0; i < cells.size(); ++i) {
      if (inside.contains(cells[i])) values[i] = islands.at<uint8_t>(cells[i]);
    }
    return values;
  };
  JoinAreasAtFurnitureGaps(graph, model, closed, from_raster, max_piece_m2, plan);
}

void JoinAreasAtFurnitureGaps(const proto::CutGraph& graph, const PlanModel& model,
                              const std::vector<bool>& closed, const IslandsAt& islands_at,
                              double max_piece_m2, AreaPlan* plan) {
  const int area_count = static_cast<int>(plan->areas.size());
  const double max_piece_px = max_piece_m2 / (model.resolution_m * model.resolution_m);
  // Pairs of areas that meet at a vertex where the opening (the narrower of
  // their two sides) has an island for a jamb, and room-less areas that have
  // any other opening.
  std::vector<std::pair<int, int>> gaps;
  std::vector<bool> enclosed(area_count, true);
  const std::vector<std::map<int, VertexOpening>>& openings = model.openings;
  // Calls `each(a, b, narrower)` for every pair of areas at a vertex that is
  // not closed.
  auto for_each_pair = [&](auto each) {
    for (int vertex = 0; vertex < graph.vertices_size(); ++vertex) {
      if (closed[vertex]) continue;
      const std::map<int, VertexOpening>& at = openings[vertex];
      for (auto a = at.begin(); a != at.end(); ++a) {
        for (auto b = std::next(a); b != at.end(); ++b) {
          each(a->first, b->first,
               a->second.width_px <= b->second.width_px ? a->second : b->second);
        }
      }
    }
  };
  // The island values of every jamb's cells, asked at once.
  IslandValues islands;
  for_each_pair([&](int, int, const VertexOpening& narrower) {
    AddCellsAround(narrower.left, &islands.cells);
    AddCellsAround(narrower.right, &islands.cells);
  });
  std::sort(islands.cells.begin(), islands.cells.end(), RowMajor);
  islands.cells.erase(std::unique(islands.cells.begin(), islands.cells.end()), islands.cells.end());
  islands.values = islands_at(islands.cells);
  for_each_pair([&](int a, int b, const VertexOpening& narrower) {
    if (OnIsland(islands, narrower.left) || OnIsland(islands, narrower.right)) {
      if (std::min(model.shapes[a].area_px, model.shapes[b].area_px) <= max_piece_px) {
        gaps.emplace_back(a, b);
      }
    } else {
      enclosed[a] = enclosed[b] = false;
    }
  });
  const auto is_room = [&](int k) { return plan->areas[k].kind == proto::AREA_ROOM; };
  DisjointSets groups(area_count);
  // Rooms with rooms, and room-less areas that open only through gaps with
  // rooms and with each other.
  for (const auto& [a, b] : gaps) {
    if ((is_room(a) || enclosed[a]) && (is_room(b) || enclosed[b])) groups.Union(a, b);
  }
  // Then room-less areas with each other (clutter in a corridor), unless one
  // of them is part of a room by now.
  std::set<int> groups_with_rooms;
  for (int k = 0; k < area_count; ++k) {
    if (is_room(k)) groups_with_rooms.insert(groups.Find(k));
  }
  for (const auto& [a, b] : gaps) {
    if (!groups_with_rooms.count(groups.Find(a)) && !groups_with_rooms.count(groups.Find(b))) {
      groups.Union(a, b);
    }
  }
  ApplyGroups(groups, plan);
}

}  // namespace areagraph
