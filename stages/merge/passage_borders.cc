#include "stages/merge/passage_borders.h"

#include <algorithm>
#include <limits>
#include <map>
#include <utility>

#include "stages/geometry/disjoint_sets.h"

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

// Of the chains between one of the passage's areas and another area that
// no passage lies on yet, the nearest to the passage point within its
// width; -1 if none.
int NearestFreeChain(const PassagePlan& passage, const PlanarPartition& partition,
                     const std::map<int, int>& area_of_label,
                     const std::map<int, size_t>& passage_on_chain) {
  int best = -1;
  double best_distance = passage.width_px;
  for (size_t c = 0; c < partition.chains.size(); ++c) {
    const BorderChain& chain = partition.chains[c];
    const auto left = area_of_label.find(chain.left), right = area_of_label.find(chain.right);
    if (left == area_of_label.end() || right == area_of_label.end()) continue;
    const bool touches = left->second == passage.area_a || left->second == passage.area_b ||
                         right->second == passage.area_a || right->second == passage.area_b;
    if (!touches || passage_on_chain.count(static_cast<int>(c))) continue;
    const double d = DistanceToChain(passage.point, chain.points);
    if (d <= best_distance) best_distance = d, best = static_cast<int>(c);
  }
  return best;
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
    const auto labels = std::minmax(label_of_area[passage.area_a], label_of_area[passage.area_b]);
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

  // Areas connected through the passages on borders.
  DisjointSets connected(label_of_area.size());
  for (const PassageOnBorder& p : placed) {
    if (p.chain >= 0) connected.Union(p.passage.area_a, p.passage.area_b);
  }
  std::map<int, int> area_of_label;
  for (size_t id = 0; id < label_of_area.size(); ++id) {
    area_of_label[label_of_area[id]] = static_cast<int>(id);
  }
  std::vector<PassageOnBorder> kept;
  for (PassageOnBorder p : placed) {
    const int a = p.passage.area_a, b = p.passage.area_b;
    if (p.chain < 0 && connected.Find(a) == connected.Find(b)) continue;
    if (p.chain < 0) {
      // The opening is real but the raster gave the cells around it to a
      // third area: it is the free border nearby of one of the two areas.
      const int c = NearestFreeChain(p.passage, partition, area_of_label, passage_on_chain);
      if (c >= 0) {
        const int x = area_of_label.at(partition.chains[c].left);
        const int y = area_of_label.at(partition.chains[c].right);
        DisjointSets trial = connected;
        trial.Union(x, y);
        if (trial.Find(a) == trial.Find(b)) {
          connected = trial;
          passage_on_chain[c] = kept.size();
          p.chain = c;
          p.passage.area_a = y == a || x == b ? y : x;
          p.passage.area_b = y == a || x == b ? x : y;
        }
      }
    }
    kept.push_back(p);
  }
  return kept;
}

}  // namespace areagraph
