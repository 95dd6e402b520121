#include "stages/merge/passage_borders.h"

#include <algorithm>
#include <limits>
#include <map>
#include <utility>

namespace areagraph {
namespace {

double DistanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                         const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

double DistanceToChain(const Eigen::Vector2d& p, const PointList& chain) {
  double nearest = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i + 1 < chain.size(); ++i) {
    nearest = std::min(nearest, DistanceToSegment(p, chain[i], chain[i + 1]));
  }
  return nearest;
}

}  // namespace

std::vector<PassageOnBorder> PlacePassagesOnBorders(const std::vector<PassagePlan>& passages,
                                                    const PlanarPartition& partition,
                                                    const std::vector<int>& label_of_area) {
  std::map<std::pair<int, int>, std::vector<int>> chains_between;
  for (size_t c = 0; c < partition.chains.size(); ++c) {
    const BorderChain& chain = partition.chains[c];
    chains_between[std::minmax(chain.left, chain.right)].push_back(static_cast<int>(c));
  }
  std::vector<PassageOnBorder> placed;
  std::map<int, size_t> passage_on_chain;
  for (const PassagePlan& passage : passages) {
    const auto labels =
        std::minmax(label_of_area[passage.area_a], label_of_area[passage.area_b]);
    int best = -1;
    double best_distance = std::numeric_limits<double>::infinity();
    const auto it = chains_between.find(labels);
    if (it != chains_between.end()) {
      for (const int c : it->second) {
        const double d = DistanceToChain(passage.point, partition.chains[c].points);
        if (d < best_distance) best_distance = d, best = c;
      }
    }
    if (best >= 0) {
      const auto [seen, added] = passage_on_chain.emplace(best, placed.size());
      if (!added) {
        PassageOnBorder& twin = placed[seen->second];
        if (passage.width_px < twin.passage.width_px) twin.passage = passage;
        continue;
      }
    }
    placed.push_back({passage, best});
  }
  return placed;
}

}  // namespace areagraph
