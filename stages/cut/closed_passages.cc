#include "stages/cut/closed_passages.h"

#include <cmath>

namespace areagraph {

ClosedLines::ClosedLines(const PointList& closing_sites, double resolution_m)
    : reach_px_(kClosedPassageReachM / resolution_m) {
  for (const Eigen::Vector2d& site : closing_sites) {
    buckets_[Key(site.x(), site.y())].push_back(site);
  }
}

int64_t ClosedLines::Key(double x, double y) const {
  return (static_cast<int64_t>(std::floor(x / reach_px_)) << 32) ^
         static_cast<uint32_t>(static_cast<int32_t>(std::floor(y / reach_px_)));
}

bool ClosedLines::Near(const Eigen::Vector2d& p) const {
  if (buckets_.empty()) return false;
  for (int dx = -1; dx <= 1; ++dx) {
    for (int dy = -1; dy <= 1; ++dy) {
      auto it = buckets_.find(Key(p.x() + dx * reach_px_, p.y() + dy * reach_px_));
      if (it == buckets_.end()) continue;
      for (const Eigen::Vector2d& site : it->second) {
        if ((site - p).norm() <= reach_px_) return true;
      }
    }
  }
  return false;
}

void MarkClosedPassages(const ClosedLines& lines, proto::CutGraph* graph) {
  if (lines.empty()) return;
  for (proto::PassagePoint& passage : *graph->mutable_passage_points()) {
    if (lines.Near({passage.position().x(), passage.position().y()})) {
      passage.set_closed_by_cut(true);
    }
  }
}

}  // namespace areagraph
