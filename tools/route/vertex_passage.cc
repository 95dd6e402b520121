#include "tools/route/vertex_passage.h"

#include <algorithm>
#include <cmath>

namespace areagraph {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Directions closer than this (sine of the angle) count as parallel.
constexpr double kAngleTolerance = 1e-9;

double Cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

bool WedgeHolds(const std::vector<OutlineVertex>& vertices, const OutlineVertex& vertex,
                const Vec2& direction) {
  for (const CornerWedge& wedge : vertex.wedges) {
    const Vec2 next = vertices[wedge.next].at - vertex.at;
    double angle = std::atan2(Cross(next, direction), next.dot(direction));
    if (angle < 0) angle += 2 * kPi;
    if (angle > kAngleTolerance && angle < wedge.angle - kAngleTolerance) return true;
  }
  return false;
}

std::vector<FreeStretch> FreeStretches(const std::vector<OutlineVertex>& vertices,
                                       const OutlineVertex& vertex) {
  const std::vector<CornerWedge>& wedges = vertex.wedges;
  std::vector<char> used(wedges.size(), 0);
  std::vector<FreeStretch> stretches;
  auto chain = [&](size_t first) {
    FreeStretch stretch;
    size_t last = first;
    used[first] = 1;
    stretch.angle = wedges[first].angle;
    stretch.areas.push_back(wedges[first].area);
    while (!wedges[last].previous_is_wall) {
      size_t following = wedges.size();
      for (size_t w = 0; w < wedges.size(); ++w) {
        if (!used[w] && wedges[w].next == wedges[last].previous) following = w;
      }
      if (following == wedges.size()) break;
      stretch.rays.push_back(wedges[last].previous);
      used[following] = 1;
      stretch.angle += wedges[following].angle;
      stretch.areas.push_back(wedges[following].area);
      last = following;
    }
    if (!wedges[first].next_is_wall) stretch.rays.push_back(wedges[first].next);
    stretch.from_wall = (vertices[wedges[first].next].at - vertex.at).normalized();
    stretch.to_wall = (vertices[wedges[last].previous].at - vertex.at).normalized();
    std::sort(stretch.areas.begin(), stretch.areas.end());
    stretch.areas.erase(std::unique(stretch.areas.begin(), stretch.areas.end()),
                        stretch.areas.end());
    stretches.push_back(std::move(stretch));
  };
  for (size_t w = 0; w < wedges.size(); ++w) {
    if (wedges[w].next_is_wall) chain(w);
  }
  // No wall meets the vertex: one stretch all round.
  if (stretches.empty() && !wedges.empty()) {
    chain(0);
    stretches.back().walled = false;
  }
  return stretches;
}

VertexPassage PassThrough(const std::vector<OutlineVertex>& vertices, const OutlineVertex& vertex,
                          const Vec2& unit) {
  VertexPassage passage;
  bool left = false, right = false;
  for (const Vec2& wall : vertex.wall_directions) {
    const Vec2 wall_unit = wall.normalized();
    const double side = Cross(unit, wall_unit);
    if (side > kAngleTolerance) {
      left = true;
    } else if (side < -kAngleTolerance) {
      right = true;
    } else if (wall_unit.dot(unit) > 0) {
      passage.ahead = true;
    } else {
      passage.behind = true;
    }
  }
  if (!passage.ahead && !passage.behind) {
    passage.crosses = left && right;
    return passage;
  }
  const Vec2 left_normal(-unit.y(), unit.x());
  if (!left && WedgeHolds(vertices, vertex, left_normal)) passage.banks |= kLeftBank;
  if (!right && WedgeHolds(vertices, vertex, -left_normal)) passage.banks |= kRightBank;
  return passage;
}

}  // namespace areagraph
