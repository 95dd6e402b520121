#include "stages/cut/door_sites.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "stages/cut/wall_probes.h"
#include "stages/cut/width_estimate.h"
#include "stages/geometry/furniture_shape.h"
#include "stages/geometry/wall_thickness.h"

namespace areagraph {
namespace {
// The Topology Graph's edges with the arc length (px) at each path point,
// and the edges that meet at each vertex.
struct EdgeArcs {
  explicit EdgeArcs(const proto::TopologyGraph& topology) : incident(topology.vertices_size()) {
    for (int e = 0; e < topology.edges_size(); ++e) {
      const proto::GraphEdge& edge = topology.edges(e);
      std::vector<double> arc(edge.path_size(), 0.0);
      for (int i = 1; i < edge.path_size(); ++i) {
        arc[i] = arc[i - 1] + std::hypot(edge.path(i).x() - edge.path(i - 1).x(),
                                         edge.path(i).y() - edge.path(i - 1).y());
      }
      arcs.push_back(std::move(arc));
      for (const int v : {edge.source(), edge.target()}) {
        if (v >= 0 && v < topology.vertices_size()) incident[v].push_back(e);
      }
    }
  }
  std::vector<std::vector<double>> arcs;
  std::vector<std::vector<int>> incident;
};

// Free width (px) for a clearance (px) measured from obstacle cell centres.
double FreeWidthPx(double clearance_px) { return std::max(0.0, 2 * clearance_px - 1); }

// The widest free width (px) along `edge` within arc [low, high], sampled
// about every pixel: a point of a Voronoi segment is as far from the
// segment's site as its clearance.
double WidestOnEdge(const proto::GraphEdge& edge, const std::vector<double>& arc, double low,
                    double high) {
  double widest = 0;
  const int segments = std::min({edge.path_size() - 1, edge.left_sites_size()});
  for (int s = 0; s < segments; ++s) {
    if (arc[s + 1] < low || arc[s] > high) continue;
    const Eigen::Vector2d p(edge.path(s).x(), edge.path(s).y());
    const Eigen::Vector2d q(edge.path(s + 1).x(), edge.path(s + 1).y());
    const Eigen::Vector2d site(edge.left_sites(s).x(), edge.left_sites(s).y());
    const double length = arc[s + 1] - arc[s];
    const int steps = std::max(1, static_cast<int>(std::ceil(length)));
    for (int k = 0; k <= steps; ++k) {
      const double at = arc[s] + length * k / steps;
      if (at < low || at > high) continue;
      const Eigen::Vector2d point = p + (q - p) * (static_cast<double>(k) / steps);
      widest = std::max(widest, FreeWidthPx((point - site).norm()));
    }
  }
  return widest;
}

// The widest free width (px) within `reach_px` of vertex `vertex` on the
// edges that meet there, except edge `except`.
double WidestNearVertex(const proto::TopologyGraph& topology, const EdgeArcs& arcs, int vertex,
                        int except, double reach_px) {
  double widest = 0;
  if (vertex < 0 || vertex >= topology.vertices_size()) return widest;
  widest = FreeWidthPx(topology.vertices(vertex).clearance_px());
  for (const int e : arcs.incident[vertex]) {
    if (e == except) continue;
    const proto::GraphEdge& edge = topology.edges(e);
    const std::vector<double>& arc = arcs.arcs[e];
    if (edge.source() == vertex) widest = std::max(widest, WidestOnEdge(edge, arc, 0, reach_px));
    if (edge.target() == vertex) {
      widest = std::max(widest, WidestOnEdge(edge, arc, arc.back() - reach_px, arc.back()));
    }
  }
  return widest;
}

// Whether the free width (px) along edge `e` grows clearly above `gap_px`
// (IsConstriction's rise) within `reach_px` of arc `at_px` on at least one
// side, looking past the edge's ends into the edges that meet there: a door
// opens into a wider space, while a cross-section of a corridor (between
// two doors facing each other) has the corridor's width on both sides.
bool WidensOnOneSide(const proto::TopologyGraph& topology, const EdgeArcs& arcs, int e,
                     double at_px, double gap_px, double reach_px, double rise_px,
                     double* before_px, double* after_px) {
  const proto::GraphEdge& edge = topology.edges(e);
  const std::vector<double>& arc = arcs.arcs[e];
  double before = WidestOnEdge(edge, arc, at_px - reach_px, at_px);
  double after = WidestOnEdge(edge, arc, at_px, at_px + reach_px);
  if (at_px < reach_px) {
    before = std::max(before, WidestNearVertex(topology, arcs, edge.source(), e, reach_px - at_px));
  }
  if (arc.back() - at_px < reach_px) {
    after = std::max(
        after, WidestNearVertex(topology, arcs, edge.target(), e, reach_px - (arc.back() - at_px)));
  }
  *before_px = before, *after_px = after;
  const double needed = gap_px + std::max(rise_px, kDoorRiseRatio * gap_px);
  return before >= needed || after >= needed;
}

}  // namespace

struct WallGapFinder::Impl {
  Impl(const proto::TopologyGraph& topology, const ObstacleLabels& obstacles, double resolution_m,
       double structure_m, double min_gap_m, double max_gap_m, bool short_tips,
       const cv::Mat* free_spaces)
      : topology(topology),
        resolution_m(resolution_m),
        walls(obstacles, structure_m / resolution_m, free_spaces),
        arcs(topology),
        short_tips(short_tips),
        run_px(kJambRunM / resolution_m),
        reach_px(kDoorReachM / resolution_m),
        rise_px(kDoorRiseM / resolution_m),
        max_thickness_px(kMaxWallThicknessM / resolution_m),
        max_gap_px(max_gap_m / resolution_m + 1),
        min_gap_px(min_gap_m / resolution_m + 1),
        min_tip_px(kMinWallPieceM / resolution_m) {}

  // The wall gap of segment `s` of edge `e` (sites a and b), if it is one;
  // its line is a to b.
  bool Find(int e, int s, Opening* found) const;

  const proto::TopologyGraph& topology;
  const double resolution_m;
  const WallStructure walls;
  const EdgeArcs arcs;
  const bool short_tips;
  const double run_px, reach_px, rise_px, max_thickness_px, max_gap_px, min_gap_px, min_tip_px;
};

WallGapFinder::WallGapFinder(const proto::TopologyGraph& topology, const ObstacleLabels& obstacles,
                             double resolution_m, double structure_m, double min_gap_m,
                             double max_gap_m, bool short_tips, const cv::Mat* free_spaces)
    : impl_(std::make_unique<Impl>(topology, obstacles, resolution_m, structure_m, min_gap_m,
                                   max_gap_m, short_tips, free_spaces)) {}

WallGapFinder::~WallGapFinder() = default;

bool WallGapFinder::Impl::Find(int e, int s, Opening* found) const {
  const proto::GraphEdge& edge = topology.edges(e);
  const Eigen::Vector2d a(edge.left_sites(s).x(), edge.left_sites(s).y());
  const Eigen::Vector2d b(edge.right_sites(s).x(), edge.right_sites(s).y());
  const double span = (b - a).norm();
  if (span > max_gap_px || span < min_gap_px) return false;
  // The gap's middle must lie on this segment: its narrowest crossing.
  const Eigen::Vector2d p(edge.path(s).x(), edge.path(s).y());
  const Eigen::Vector2d q(edge.path(s + 1).x(), edge.path(s + 1).y());
  const double length2 = (q - p).squaredNorm();
  if (length2 <= 0) return false;
  const double t = (0.5 * (a + b) - p).dot(q - p) / length2;
  if (t < 0 || t > 1) return false;
  const int label_a = walls.LabelAt(a), label_b = walls.LabelAt(b);
  const bool wall_a = walls.IsStructure(label_a), wall_b = walls.IsStructure(label_b);
  if (!wall_a && !wall_b) return false;
  const Eigen::Vector2d along = (b - a) / span;
  const int space = walls.SpaceAt(0.5 * (a + b));
  if (!WallRunsOn(walls, a, -along, run_px, space) || !WallRunsOn(walls, b, along, run_px, space)) {
    return false;
  }
  const bool tip_a = IsThinWallEnd(walls, a, -along, run_px, max_thickness_px);
  const bool tip_b = IsThinWallEnd(walls, b, along, run_px, max_thickness_px);
  if (!tip_a && !tip_b) return false;
  // With short_tips, a thin wall end facing the structure may be a short
  // piece of wall (between two doors, a partition, a block of a row).
  auto jamb = [&](bool wall, bool tip, int label) {
    return wall || (short_tips && tip && walls.Longest(label) >= min_tip_px);
  };
  if (!jamb(wall_a, tip_a, label_a) || !jamb(wall_b, tip_b, label_b)) return false;
  const std::vector<double>& arc = arcs.arcs[e];
  const double at_px = arc[s] + t * (arc[s + 1] - arc[s]);
  double before = 0, after = 0;
  if (!WidensOnOneSide(topology, arcs, e, at_px, span - 1, reach_px, rise_px, &before, &after)) {
    return false;
  }
  *found = Opening();
  found->kind = proto::Opening::WALL_GAP;
  found->position = p + t * (q - p);
  found->width_m = (span - 1) * resolution_m;
  found->has_jambs = true;
  found->jamb_a = a, found->jamb_b = b;
  found->side_a_m = before * resolution_m, found->side_b_m = after * resolution_m;
  found->closed = true;
  found->lines = {{a, b}};
  return true;
}

std::vector<Opening> WallGapFinder::Openings(int begin, int end) const {
  const Impl& in = *impl_;
  std::vector<Opening> openings;
  for (int e = begin; e < end; ++e) {
    const proto::GraphEdge& edge = in.topology.edges(e);
    const int segments =
        std::min({edge.path_size() - 1, edge.left_sites_size(), edge.right_sites_size()});
    bool in_run = false;  // consecutive segments across one gap
    for (int s = 0; s < segments; ++s) {
      Opening found;
      if (!in.Find(e, s, &found)) {
        in_run = false;
        continue;
      }
      if (in_run) {
        Opening& run = openings.back();
        run.lines.push_back(found.lines.front());
        // The run's place and width are its narrowest crossing's.
        if (found.width_m < run.width_m) {
          found.lines = std::move(run.lines);
          run = std::move(found);
        }
      } else {
        openings.push_back(std::move(found));
      }
      in_run = true;
    }
  }
  return openings;
}

PointList WallGapSites(const proto::TopologyGraph& topology, const ObstacleLabels& obstacles,
                       double resolution_m, double structure_m, double min_gap_m, double max_gap_m,
                       bool short_tips, const cv::Mat* free_spaces) {
  if (max_gap_m <= 0) return PointList();
  return ClosingSites(WallGapFinder(topology, obstacles, resolution_m, structure_m, min_gap_m,
                                    max_gap_m, short_tips, free_spaces)
                          .Openings(0, topology.edges_size()));
}

std::vector<Opening> NarrowingOpenings(const proto::RoomWidthEstimate& estimate,
                                       const ObstacleLabels& obstacles, double resolution_m,
                                       double structure_m, const cv::Mat* free_spaces) {
  std::vector<Opening> openings;
  if (estimate.doors_size() == 0) return openings;
  const WallStructure walls(obstacles, structure_m / resolution_m, free_spaces);
  const double run_px = kJambRunM / resolution_m;
  for (const proto::DetectedWidth& door : estimate.doors()) {
    Opening& opening = openings.emplace_back();
    const Eigen::Vector2d p(door.position().x(), door.position().y());
    opening.position = p;
    opening.width_m = door.width_m();
    opening.side_a_m = door.side_a_m(), opening.side_b_m = door.side_b_m();
    const double reach = 0.5 * door.width_m() / resolution_m + 2;
    Eigen::Vector2d a, b;
    if (!NearestObstacle(walls, p, reach, nullptr, &a)) continue;
    if (!NearestObstacle(walls, p, reach + 1, &a, &b)) continue;
    opening.has_jambs = true;
    opening.jamb_a = a, opening.jamb_b = b;
    opening.lines = {{a, b}};
    if (!walls.IsStructure(walls.LabelAt(a)) || !walls.IsStructure(walls.LabelAt(b))) continue;
    const double span = (b - a).norm();
    if (span < 1) continue;
    const Eigen::Vector2d along = (b - a) / span;
    const int space = walls.SpaceAt(p);
    opening.closed =
        WallRunsOn(walls, a, -along, run_px, space) && WallRunsOn(walls, b, along, run_px, space);
  }
  return openings;
}

PointList DoorClosingSites(const proto::RoomWidthEstimate& estimate,
                           const ObstacleLabels& obstacles, double resolution_m, double structure_m,
                           const cv::Mat* free_spaces) {
  return ClosingSites(
      NarrowingOpenings(estimate, obstacles, resolution_m, structure_m, free_spaces));
}

}  // namespace areagraph
