#include "stages/cut/width_estimate.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "stages/cut/edge_track.h"
#include "stages/cut/reach_extremes.h"
#include "stages/geometry/edge_polygon.h"
#include "stages/geometry/point_buckets.h"

namespace areagraph {
namespace {

// One edge sampled about every pixel: free width (m) and arc length (m).
struct WidthProfile {
  int source = 0;
  int target = 0;
  std::vector<Eigen::Vector2d> points;
  std::vector<double> width_m;
  std::vector<double> arc_m;
};

WidthProfile SampleEdge(const proto::GraphEdge& edge, double resolution_m) {
  const EdgeTrack track(edge);
  WidthProfile profile;
  profile.source = edge.source();
  profile.target = edge.target();
  auto add = [&](const PathPosition& at) {
    profile.points.push_back(track.PointAt(at));
    profile.width_m.push_back(std::max(0.0, 2 * track.ClearanceAt(at) - 1) * resolution_m);
    profile.arc_m.push_back(track.ArcAt(at) * resolution_m);
  };
  for (int segment = 0; segment < track.segment_count(); ++segment) {
    const double length = (track.path()[segment + 1] - track.path()[segment]).norm();
    const int steps = std::max(1, static_cast<int>(std::ceil(length)));
    for (int k = 0; k < steps; ++k) add({segment, static_cast<double>(k) / steps});
  }
  add(track.End());
  return profile;
}

// The widest point within `reach_m` of vertex `vertex` on the edges that
// meet there, except edge `except`; 0 when there are none.
double WidestNearVertex(const std::vector<WidthProfile>& profiles,
                        const std::vector<EndMaxima>& maxima,
                        const std::vector<std::vector<int>>& incident, int vertex, int except,
                        double reach_m) {
  double widest = 0;
  for (int e : incident[vertex]) {
    if (e == except) continue;
    const WidthProfile& p = profiles[e];
    if (p.source == vertex)
      widest = WidestFromStart(maxima[e], p.width_m, p.arc_m, reach_m, widest);
    if (p.target == vertex) widest = WidestFromEnd(maxima[e], p.width_m, p.arc_m, reach_m, widest);
  }
  return widest;
}

bool IsConstriction(double narrowest, double widest_beside) {
  return widest_beside >= narrowest + std::max(kDoorRiseM, kDoorRiseRatio * narrowest);
}

void FindDoors(const std::vector<WidthProfile>& profiles,
               const std::vector<std::vector<int>>& incident,
               std::vector<proto::DetectedWidth>* doors) {
  std::vector<EndMaxima> maxima;
  maxima.reserve(profiles.size());
  for (const WidthProfile& p : profiles) maxima.push_back(MaximaFromEnds(p.width_m, p.arc_m));
  for (size_t e = 0; e < profiles.size(); ++e) {
    const WidthProfile& p = profiles[e];
    const int n = static_cast<int>(p.width_m.size());
    const ReachExtremes near = ExtremesWithinReach(p.width_m, p.arc_m, kDoorReachM);
    int run_start = -1;                    // a run of equal narrowest samples (a door's depth)
    std::vector<double> sides_a, sides_b;  // the widest beside each sample of the run
    for (int i = 0; i <= n; ++i) {
      bool door = false;
      if (i < n) {
        const double width = p.width_m[i];
        const bool narrowest = near.before_min[i] >= width && near.after_min[i] >= width;
        double left = near.before_max[i], right = near.after_max[i];
        if (near.reaches_start[i]) {
          left = std::max(left, WidestNearVertex(profiles, maxima, incident, p.source, e,
                                                 kDoorReachM - p.arc_m[i]));
        }
        if (near.reaches_end[i]) {
          right = std::max(right, WidestNearVertex(profiles, maxima, incident, p.target, e,
                                                   kDoorReachM - (p.arc_m.back() - p.arc_m[i])));
        }
        door = narrowest && IsConstriction(width, left) && IsConstriction(width, right);
        if (door) sides_a.push_back(left), sides_b.push_back(right);
      }
      if (door && run_start < 0) run_start = i;
      if (!door && run_start >= 0) {
        const int middle = (run_start + i - 1) / 2;
        proto::DetectedWidth found;
        found.mutable_position()->set_x(p.points[middle].x());
        found.mutable_position()->set_y(p.points[middle].y());
        found.set_width_m(p.width_m[middle]);
        found.set_side_a_m(sides_a[middle - run_start]);
        found.set_side_b_m(sides_b[middle - run_start]);
        doors->push_back(found);
        run_start = -1;
        sides_a.clear(), sides_b.clear();
      }
    }
  }
}

void FindCorridors(const std::vector<WidthProfile>& profiles,
                   std::vector<proto::DetectedWidth>* corridors) {
  for (const WidthProfile& p : profiles) {
    const size_t n = p.width_m.size();
    SteadyRuns runs(p.width_m, SteadyWidthSpreadM);
    size_t i = 0;
    while (i < n) {
      const size_t j = runs.EndFrom(static_cast<int>(i));
      const double length = p.arc_m[j - 1] - p.arc_m[i];
      if (length < kCorridorMinLengthM) {
        ++i;
        continue;
      }
      std::vector<double> widths(p.width_m.begin() + i, p.width_m.begin() + j);
      std::nth_element(widths.begin(), widths.begin() + widths.size() / 2, widths.end());
      const size_t middle = (i + j - 1) / 2;
      proto::DetectedWidth found;
      found.mutable_position()->set_x(p.points[middle].x());
      found.mutable_position()->set_y(p.points[middle].y());
      found.set_width_m(widths[widths.size() / 2]);
      found.set_length_m(length);
      corridors->push_back(found);
      i = j;
    }
  }
}

// Keeps the widest of doors closer than kDoorReachM to each other (one door
// seen from two edges), widest first.
std::vector<proto::DetectedWidth> OnePerPlace(std::vector<proto::DetectedWidth> doors,
                                              double resolution_m) {
  std::sort(doors.begin(), doors.end(),
            [](const auto& a, const auto& b) { return a.width_m() > b.width_m(); });
  std::vector<proto::DetectedWidth> kept;
  // Buckets twice the reach wide: only kept doors in the nine around a door
  // can be near it (thousands of doors on cluttered maps).
  PointBuckets kept_places(2 * kDoorReachM / resolution_m);
  for (const proto::DetectedWidth& door : doors) {
    const double x = door.position().x(), y = door.position().y();
    const bool near = kept_places.AnyNear(x, y, [&](int k) {
      const proto::Point2& other = kept[k].position();
      return std::hypot(x - other.x(), y - other.y()) * resolution_m < kDoorReachM;
    });
    if (near) continue;
    kept_places.Add(x, y, static_cast<int>(kept.size()));
    kept.push_back(door);
  }
  return kept;
}

// The narrowest corridor stretch's width; 0 for none.
double NarrowestCorridorM(const std::vector<proto::DetectedWidth>& corridors) {
  double narrowest = 0;
  for (const proto::DetectedWidth& corridor : corridors) {
    if (narrowest == 0 || corridor.width_m() < narrowest) narrowest = corridor.width_m();
  }
  return narrowest;
}

}  // namespace

proto::RoomWidthEstimate EstimateRoomWidth(const proto::TopologyGraph& topology,
                                           double resolution_m, double robot_width_m,
                                           double fallback_m, bool above_doors,
                                           double door_margin_m) {
  std::vector<int> all(topology.edges_size());
  std::iota(all.begin(), all.end(), 0);
  return EstimateRoomWidth(topology, all, resolution_m, robot_width_m, fallback_m, above_doors,
                           door_margin_m);
}

proto::RoomWidthEstimate EstimateRoomWidth(const proto::TopologyGraph& topology,
                                           const std::vector<int>& edges, double resolution_m,
                                           double robot_width_m, double fallback_m,
                                           bool above_doors, double door_margin_m) {
  std::vector<WidthProfile> profiles;
  std::vector<std::vector<int>> incident(topology.vertices_size());
  for (const int e : edges) {
    const proto::GraphEdge& edge = topology.edges(e);
    profiles.push_back(SampleEdge(edge, resolution_m));
    incident[edge.source()].push_back(static_cast<int>(profiles.size()) - 1);
    if (edge.target() != edge.source()) {
      incident[edge.target()].push_back(static_cast<int>(profiles.size()) - 1);
    }
  }
  std::vector<proto::DetectedWidth> doors, corridors;
  FindDoors(profiles, incident, &doors);
  FindCorridors(profiles, &corridors);
  doors = OnePerPlace(std::move(doors), resolution_m);

  proto::RoomWidthEstimate estimate;
  estimate.set_automatic(true);
  for (const auto& door : doors) *estimate.add_doors() = door;
  for (const auto& corridor : corridors) *estimate.add_corridors() = corridor;
  std::vector<double> widths;
  for (const proto::DetectedWidth& door : doors) widths.push_back(door.width_m());
  const double door = WidestDoorM(widths);
  const double corridor = NarrowestCorridorM(corridors);
  estimate.set_widest_door_m(door);
  estimate.set_narrowest_corridor_m(corridor);
  estimate.set_room_width_m(
      WidthRule(door, corridor, fallback_m, above_doors, door_margin_m, robot_width_m));
  return estimate;
}

double WidestDoorM(const std::vector<double>& widths_widest_first) {
  if (widths_widest_first.empty()) return 0;
  return widths_widest_first[widths_widest_first.size() / 10];
}

double WidthRule(double door_m, double corridor_m, double fallback_m, bool above_doors,
                 double door_margin_m, double robot_width_m) {
  double width = fallback_m;
  // Widths within the paper's margin count as equal, and then W stays above
  // the door: a disk that passes doors merges rooms, which costs far more
  // than a corridor cut in two.
  if (door_m > 0 && (above_doors || corridor_m <= 0 || door_m < corridor_m + kPaperWidthMarginM)) {
    width = door_m + door_margin_m;
  } else if (corridor_m > 0) {
    width = corridor_m - kPaperWidthMarginM;
  }
  return std::max(width, MinRoomWidthM(robot_width_m));
}

}  // namespace areagraph
