#include "stages/merge/furniture_gap_joining.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <opencv2/imgproc.hpp>
#include <set>
#include <utility>
#include <vector>

#include "stages/geometry/disjoint_sets.h"
#include "stages/geometry/distance_transform.h"
#include "stages/geometry/edge_polygon.h"
#include "stages/geometry/enclosed_pockets.h"
#include "stages/geometry/region_boxes.h"
#include "stages/geometry/ring_simplicity.h"
#include "stages/geometry/wall_thickness.h"
#include "stages/merge/room_joining.h"
#include "stages/merge/vertex_openings.h"

namespace areagraph {
namespace {

// Whether the cell under a site (a cell centre), or one of its 8 neighbours,
// belongs to an island: 1 when one stands free, 2 when one stands only
// against a wall, 0 otherwise.
int OnIsland(const cv::Mat& islands, const Eigen::Vector2d& site) {
  int found = 0;
  const int col = static_cast<int>(std::floor(site.x()));
  const int row = static_cast<int>(std::floor(site.y()));
  for (int dr = -1; dr <= 1; ++dr) {
    for (int dc = -1; dc <= 1; ++dc) {
      const int c = col + dc, r = row + dr;
      if (c < 0 || r < 0 || c >= islands.cols || r >= islands.rows) continue;
      const int value = islands.at<uint8_t>(r, c);
      if (value == 1) return 1;
      if (value != 0) found = value;
    }
  }
  return found;
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

// The same for the labels marked in `wanted`, each measured within its box:
// the cells nearest to a region's cells outside it are free (an 8-connected
// region does not touch another), and lie within one cell of its box.
std::vector<float> DeepestPerRegion(const cv::Mat& labels, const cv::Mat& stats,
                                    const std::vector<uint8_t>& wanted) {
  std::vector<float> deepest(wanted.size(), 0);
  for (size_t k = 1; k < wanted.size(); ++k) {
    if (!wanted[k]) continue;
    const cv::Rect box(
        stats.at<int>(int(k), cv::CC_STAT_LEFT), stats.at<int>(int(k), cv::CC_STAT_TOP),
        stats.at<int>(int(k), cv::CC_STAT_WIDTH), stats.at<int>(int(k), cv::CC_STAT_HEIGHT));
    deepest[k] = float(DeepestDistance(LabelMaskInBox(labels, int(k), box)));
  }
  return deepest;
}

// Marks (`value` in `out`, where it is still 0) the cells of every 8-connected region of `obstacle`
// that touches no image border, is at most `max_px` long, at least
// `min_thickness_px` thick (twice its deepest cell's depth), fills
// kMinFurnitureSolidity of its smallest enclosing rectangle and, unless
// `max_elongation` is 0, is at most that many times as long as the
// rectangle is wide. `depth` is ObstacleDepth(obstacle), when the caller has
// it already.
void MarkIslands(const cv::Mat& obstacle, double min_thickness_px, double max_px,
                 double max_elongation, uint8_t value, cv::Mat* out, cv::Mat depth = cv::Mat()) {
  const int width = obstacle.cols, height = obstacle.rows;
  cv::Mat labels, stats;
  const int count = LabelRegionsWithBoxes(obstacle, 8, &labels, &stats);
  std::vector<uint8_t> island(count, 0);
  for (int k = 1; k < count; ++k) {
    const int x = stats.at<int>(k, cv::CC_STAT_LEFT), y = stats.at<int>(k, cv::CC_STAT_TOP);
    const int w = stats.at<int>(k, cv::CC_STAT_WIDTH), h = stats.at<int>(k, cv::CC_STAT_HEIGHT);
    const bool border = x == 0 || y == 0 || x + w == width || y + h == height;
    island[k] = !border && std::max(w, h) <= max_px;
  }
  const std::vector<float> deepest = depth.empty() && ComputedExactly(obstacle.size())
                                         ? DeepestPerRegion(labels, stats, island)
                                         : DeepestPerLabel(obstacle, labels, count, depth);
  for (int k = 1; k < count; ++k) {
    island[k] = island[k] && 2 * deepest[k] >= min_thickness_px;
  }
  // Candidates must fill most of their smallest enclosing rectangle.
  std::vector<std::vector<cv::Point>> points(count);
  for (int r = 0; r < height; ++r) {
    const int* row = labels.ptr<int>(r);
    for (int c = 0; c < width; ++c) {
      if (island[row[c]]) points[row[c]].emplace_back(c, r);
    }
  }
  for (int k = 1; k < count; ++k) {
    if (!island[k]) continue;
    const cv::RotatedRect box = cv::minAreaRect(points[k]);
    const double box_cells = (box.size.width + 1) * (box.size.height + 1);
    island[k] = stats.at<int>(k, cv::CC_STAT_AREA) >= kMinFurnitureSolidity * box_cells;
    // A piece of wall between two doors is long and narrow, a desk is not.
    const double longer = std::max(box.size.width, box.size.height) + 1;
    const double shorter = std::min(box.size.width, box.size.height) + 1;
    if (max_elongation > 0 && longer > max_elongation * shorter) island[k] = 0;
  }
  for (int r = 0; r < height; ++r) {
    const int* row = labels.ptr<int>(r);
    uint8_t* target = out->ptr<uint8_t>(r);
    for (int c = 0; c < width; ++c) {
      if (island[row[c]] && target[c] == 0) target[c] = value;
    }
  }
}

}  // namespace

cv::Mat FurnitureIslandCells(const proto::CleanedMap& map, double fill_pockets_m,
                             bool against_walls, double max_elongation) {
  const int width = map.frame().width_px(), height = map.frame().height_px();
  const double resolution_m = map.frame().resolution_m();
  // What cleaning removed is still no free space: a wall it broke stays one.
  cv::Mat obstacle = ObstacleMask(map.cells(), width, height);
  for (const auto* list : {&map.removed_outlier_cells(), &map.removed_furniture_cells()}) {
    for (const int index : *list) {
      if (index >= 0 && index < width * height) obstacle.data[index] = 255;
    }
  }
  if (fill_pockets_m > 0) FillEnclosedPockets(fill_pockets_m / resolution_m, &obstacle);
  // One distance transform of the obstacles for the wall thickness and the islands.
  cv::Mat depth = ObstacleDepth(obstacle);
  const double min_thickness_px = std::max(
      kMinFurnitureThicknessM / resolution_m,
      kFurnitureWallRatio * TypicalWallThickness(depth, kMaxWallThicknessM / resolution_m));
  const double max_px = kMaxFurnitureIslandM / resolution_m;
  cv::Mat out = cv::Mat::zeros(height, width, CV_8U);
  MarkIslands(obstacle, min_thickness_px, max_px, max_elongation, 1, &out, std::move(depth));
  if (against_walls) {
    // Only what is at least as thick as an island is left of the obstacles:
    // walls thinner than that go, and what stood against them is on its own.
    const int diameter = static_cast<int>(std::ceil(min_thickness_px));
    const cv::Mat disk = cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(diameter, diameter));
    cv::Mat thick;
    cv::morphologyEx(obstacle, thick, cv::MORPH_OPEN, disk);
    MarkIslands(thick, min_thickness_px, max_px, max_elongation, 2, &out);
  }
  return out;
}

void JoinAreasAtFurnitureGaps(const proto::CutGraph& graph, const cv::Mat& islands,
                              double resolution_m, bool keep_closed_doors, bool corridor_clutter,
                              AreaPlan* plan) {
  const int area_count = static_cast<int>(plan->areas.size());
  const std::vector<double> size_m2 = AreaSizesM2(graph, *plan, resolution_m);
  // Pairs of areas that meet at a vertex where the opening (the narrower of
  // their two sides) has an island for a jamb, and room-less areas that have
  // any other opening.
  std::vector<std::pair<int, int>> gaps;
  // Corridor-shaped rooms (CorridorLike) join at a gap whatever their size:
  // a bin or a cabinet in a corridor does not end it.
  std::vector<bool> corridor_like(area_count, false);
  if (corridor_clutter) {
    for (int k = 0; k < area_count; ++k) {
      corridor_like[k] =
          plan->areas[k].kind == proto::AREA_ROOM && CorridorLike(graph, plan->areas[k]);
    }
  }
  std::vector<bool> enclosed(area_count, true);
  const std::vector<std::map<int, VertexOpening>> openings = OpeningsAtVertices(graph, *plan);
  const std::vector<bool> closed = ClosedVertices(graph, keep_closed_doors);
  for (int vertex = 0; vertex < graph.vertices_size(); ++vertex) {
    const std::map<int, VertexOpening>& at = openings[vertex];
    for (auto a = at.begin(); a != at.end(); ++a) {
      for (auto b = std::next(a); b != at.end(); ++b) {
        const bool corridors = corridor_like[a->first] && corridor_like[b->first];
        // ag-cut closes a narrowing between two wider spaces whose sides are
        // structure; a bin against a corridor's wall makes one.
        if (closed[vertex] && !corridors) continue;
        const VertexOpening& narrower =
            a->second.width_px <= b->second.width_px ? a->second : b->second;
        const int left = OnIsland(islands, narrower.left);
        const int right = OnIsland(islands, narrower.right);
        const bool small =
            std::min(size_m2[a->first], size_m2[b->first]) <= kMaxFurnitureGapPieceM2;
        if ((left == 1 || right == 1) && !closed[vertex]) {
          if (small) gaps.emplace_back(a->first, b->first);
        } else if ((left == 2 || right == 2) && corridors) {
          // A bin or a cabinet against a corridor's wall, whatever the
          // corridor's size and also where ag-cut closed the narrowing.
          gaps.emplace_back(a->first, b->first);
        } else if (!closed[vertex]) {
          enclosed[a->first] = enclosed[b->first] = false;
        }
      }
    }
  }
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
