#include "stages/cut/closed_passages.h"

#include <cmath>
#include <unordered_map>
#include <vector>

namespace areagraph {

void MarkClosedPassages(const PointList& closing_sites, double resolution_m,
                        proto::CutGraph* graph) {
  if (closing_sites.empty()) return;
  const double reach_px = kClosedPassageReachM / resolution_m;
  // Sites bucketed in cells of the reach, so each passage looks at 3 x 3.
  auto key = [&](double x, double y) {
    return (static_cast<int64_t>(std::floor(x / reach_px)) << 32) ^
           static_cast<uint32_t>(static_cast<int32_t>(std::floor(y / reach_px)));
  };
  std::unordered_map<int64_t, std::vector<Eigen::Vector2d>> buckets;
  for (const Eigen::Vector2d& site : closing_sites) {
    buckets[key(site.x(), site.y())].push_back(site);
  }
  for (proto::PassagePoint& passage : *graph->mutable_passage_points()) {
    const Eigen::Vector2d p(passage.position().x(), passage.position().y());
    bool near = false;
    for (int dx = -1; dx <= 1 && !near; ++dx) {
      for (int dy = -1; dy <= 1 && !near; ++dy) {
        auto it = buckets.find(key(p.x() + dx * reach_px, p.y() + dy * reach_px));
        if (it == buckets.end()) continue;
        for (const Eigen::Vector2d& site : it->second) {
          if ((site - p).norm() <= reach_px) {
            near = true;
            break;
          }
        }
      }
    }
    if (near) passage.set_closed_by_cut(true);
  }
}

}  // namespace areagraph
