#include "stages/match/ring_pinches.h"

#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "stages/geometry/ring_area.h"

namespace areagraph {
namespace {

// The loops of `ring` between its repeated vertices (without a repeated
// closing point), the last one what is left when every inner loop is taken
// out.
std::vector<proto::Ring> Loops(const proto::Ring& ring) {
  std::vector<proto::Point2> points(ring.points().begin(), ring.points().end());
  while (points.size() > 1 && points.back().x() == points.front().x() &&
         points.back().y() == points.front().y()) {
    points.pop_back();
  }
  std::vector<proto::Ring> loops;
  std::vector<proto::Point2> path;
  std::map<std::pair<double, double>, size_t> index_in_path;
  for (const proto::Point2& p : points) {
    const std::pair<double, double> key{p.x(), p.y()};
    const auto found = index_in_path.find(key);
    if (found != index_in_path.end()) {
      // path[found..end) is a closed loop through p: take it out.
      proto::Ring loop;
      for (size_t i = found->second; i < path.size(); ++i) {
        *loop.add_points() = path[i];
        if (i > found->second) index_in_path.erase({path[i].x(), path[i].y()});
      }
      loops.push_back(std::move(loop));
      path.resize(found->second + 1);
      continue;
    }
    index_in_path[key] = path.size();
    path.push_back(p);
  }
  proto::Ring rest;
  for (const proto::Point2& p : path) *rest.add_points() = p;
  loops.push_back(std::move(rest));
  return loops;
}

// The loop of `ring` with the largest area (the ring itself without repeats).
proto::Ring LargestLoop(const proto::Ring& ring) {
  const std::vector<proto::Ring> loops = Loops(ring);
  if (loops.size() == 1) return ring;
  const proto::Ring* largest = &loops.front();
  for (const proto::Ring& loop : loops) {
    if (std::abs(TwiceSignedArea(loop)) > std::abs(TwiceSignedArea(*largest))) largest = &loop;
  }
  return *largest;
}

}  // namespace

proto::Polygon WithoutPinches(const proto::Polygon& polygon) {
  proto::Polygon result = polygon;
  *result.mutable_outer() = LargestLoop(polygon.outer());
  for (int h = 0; h < polygon.holes_size(); ++h) {
    *result.mutable_holes(h) = LargestLoop(polygon.holes(h));
  }
  return result;
}

}  // namespace areagraph
