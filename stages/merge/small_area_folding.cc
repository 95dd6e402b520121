#include "stages/merge/small_area_folding.h"

#include <algorithm>
#include <functional>
#include <map>
#include <numeric>
#include <queue>
#include <set>
#include <utility>
#include <vector>

#include "stages/geometry/region_boxes.h"

namespace areagraph {
namespace {

constexpr int kDx[4] = {1, -1, 0, 0};
constexpr int kDy[4] = {0, 0, 1, -1};

// Areas folded into others: each folded area points at the one it went into,
// which keeps its index until the end.
class FoldedAreas {
 public:
  explicit FoldedAreas(int count) : into_(count) { std::iota(into_.begin(), into_.end(), 0); }

  // The area that `area` is part of now (itself unless folded).
  int Find(int area) {
    while (into_[area] != area) {
      into_[area] = into_[into_[area]];
      area = into_[area];
    }
    return area;
  }
  void Fold(int from, int into) { into_[from] = into; }

 private:
  std::vector<int> into_;
};

// The areas that share a graph vertex with each area.
std::vector<std::set<int>> GraphNeighbours(const proto::CutGraph& graph, const AreaPlan& plan) {
  std::vector<std::set<int>> neighbours(plan.areas.size());
  for (const std::set<int>& at : AreasAtVertices(graph, plan)) {
    for (int a : at) {
      for (int b : at) {
        if (a != b) neighbours[a].insert(b);
      }
    }
  }
  return neighbours;
}

// How many cell sides `area` (with what was folded into it) shares with each
// other area, by area, looking at its cells inside `box` (which holds them all).
std::map<int, int64_t> BordersOf(const cv::Mat& labels, int area, const cv::Rect& box,
                                 FoldedAreas& folded) {
  std::map<int, int64_t> border;
  const cv::Rect inside = box & cv::Rect(0, 0, labels.cols, labels.rows);
  for (int r = inside.y; r < inside.br().y; ++r) {
    const int* row = labels.ptr<int>(r);
    for (int c = inside.x; c < inside.br().x; ++c) {
      if (row[c] <= 0 || folded.Find(row[c] - 1) != area) continue;
      for (int k = 0; k < 4; ++k) {
        const int x = c + kDx[k], y = r + kDy[k];
        if (x < 0 || y < 0 || x >= labels.cols || y >= labels.rows) continue;
        const int other = labels.at<int>(y, x);
        if (other <= 0) continue;
        const int other_area = folded.Find(other - 1);
        if (other_area != area) ++border[other_area];
      }
    }
  }
  return border;
}

// The area with the longest border (the first on ties), among the graph
// neighbours only when `graph_only`; -1 when none shares a border.
int LongestBorder(const std::map<int, int64_t>& border, const std::set<int>& neighbours,
                  bool graph_only) {
  int best = -1;
  int64_t best_length = 0;
  for (const auto& [area, length] : border) {
    if (graph_only && !neighbours.count(area)) continue;
    if (length > best_length) {
      best = area;
      best_length = length;
    }
  }
  return best;
}

// The biggest of `neighbours` (the first on ties), or -1.
int Biggest(const std::set<int>& neighbours, const std::vector<int64_t>& cells) {
  int best = -1;
  for (int area : neighbours) {
    if (best < 0 || cells[area] > cells[best]) best = area;
  }
  return best;
}

// `plan` and `raster` with the folds applied: the remaining areas keep their
// order, an area that took others gets the union of their edges (sorted),
// and every label is renumbered in one pass.
void ApplyFolds(FoldedAreas& folded, const std::vector<bool>& took_others, AreaPlan* plan,
                AreaRaster* raster) {
  const int count = static_cast<int>(plan->areas.size());
  std::vector<int> new_index(count, -1);
  AreaPlan result;
  std::vector<int64_t> cells;
  std::vector<cv::Rect> boxes;
  for (int k = 0; k < count; ++k) {
    if (folded.Find(k) != k) continue;
    new_index[k] = static_cast<int>(result.areas.size());
    result.areas.push_back(plan->areas[k]);
    if (took_others[k]) result.areas.back().edges.clear();
    cells.push_back(raster->cell_count[k]);
    boxes.push_back(raster->boxes[k]);
  }
  result.area_of_edge.resize(plan->area_of_edge.size(), -1);
  for (size_t e = 0; e < plan->area_of_edge.size(); ++e) {
    if (plan->area_of_edge[e] < 0) continue;
    const int root = folded.Find(plan->area_of_edge[e]);
    result.area_of_edge[e] = new_index[root];
    if (took_others[root]) result.areas[new_index[root]].edges.push_back(static_cast<int>(e));
  }
  std::vector<int> label_of(count + 1, 0);
  for (int k = 0; k < count; ++k) label_of[k + 1] = new_index[folded.Find(k)] + 1;
  // Run by run, and only the runs whose label changes are written.
  const int cols = raster->labels.cols;
  for (int r = 0; r < raster->labels.rows; ++r) {
    int* row = raster->labels.ptr<int>(r);
    for (int c = 0; c < cols;) {
      const int end = RunEnd(row, c, cols);
      const int label = row[c];
      if (label > 0 && label <= count && label_of[label] != label) {
        std::fill(row + c, row + end, label_of[label]);
      }
      c = end;
    }
  }
  raster->cell_count = std::move(cells);
  raster->boxes = std::move(boxes);
  *plan = std::move(result);
}

}  // namespace

void FoldSmallAreas(const proto::CutGraph& graph, int64_t min_cells, AreaPlan* plan,
                    AreaRaster* raster, const std::vector<bool>& kept) {
  const int count = static_cast<int>(plan->areas.size());
  std::vector<int64_t>& cells = raster->cell_count;
  FoldedAreas folded(count);
  // Folding keeps the boxes: the box of two areas' cells is the union of theirs.
  std::vector<cv::Rect>& box = raster->boxes;
  std::vector<std::set<int>> neighbours = GraphNeighbours(graph, *plan);
  std::vector<bool> unfoldable(count, false), took_others(count, false);
  for (int k = 0; k < count && k < static_cast<int>(kept.size()); ++k) unfoldable[k] = kept[k];
  int remaining = count;
  // Smallest first, ties to the lower index. An area that grows is queued
  // again; its older entry no longer matches its size and is skipped.
  using Entry = std::pair<int64_t, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (int k = 0; k < count; ++k) {
    if (cells[k] < min_cells) queue.push({cells[k], k});
  }
  while (!queue.empty() && remaining >= 2) {
    const auto [size, smallest] = queue.top();
    queue.pop();
    if (folded.Find(smallest) != smallest || unfoldable[smallest] || cells[smallest] != size) {
      continue;
    }
    const std::map<int, int64_t> border =
        BordersOf(raster->labels, smallest, box[smallest], folded);
    int into = LongestBorder(border, neighbours[smallest], /*graph_only=*/true);
    if (into < 0) into = LongestBorder(border, neighbours[smallest], /*graph_only=*/false);
    if (into < 0 && cells[smallest] == 0) into = Biggest(neighbours[smallest], cells);
    if (into < 0) {
      unfoldable[smallest] = true;
      continue;
    }
    folded.Fold(smallest, into);
    took_others[into] = true;
    --remaining;
    cells[into] += cells[smallest];
    if (box[smallest].area() > 0) {
      box[into] = box[into].area() == 0 ? box[smallest] : (box[into] | box[smallest]);
    }
    // `into` now meets every graph neighbour of `smallest`.
    for (int k : neighbours[smallest]) {
      neighbours[k].erase(smallest);
      if (k == into) continue;
      neighbours[k].insert(into);
      neighbours[into].insert(k);
    }
    neighbours[smallest].clear();
    if (cells[into] < min_cells && !unfoldable[into]) queue.push({cells[into], into});
  }
  ApplyFolds(folded, took_others, plan, raster);
}

}  // namespace areagraph
