#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "proto/artifacts.pb.h"
#include "tools/route/free_space.h"

namespace areagraph {

struct RouteSettings {
  // A point outside every area goes to the nearest point of an area at most
  // this far away; farther, there is no route.
  double snap_distance_m = 1.0;
  // Corners are linked when they see each other and their areas are at most
  // this many passages apart (every corner sees the corners of its own
  // area's passages, so the graph stays connected at 0); more hops make
  // straighter routes across chains of areas and a slower set-up. Chosen on
  // lab_b, lab_c, lab_d and freiburg_building79 (docs/routes.md): 2 and 1
  // gave the routes of unlimited hops there but for 0.2 % of one median.
  int link_hops = 2;
  // The same for the route's two ends.
  int end_hops = 1;
};

// A way from one point to another through the free space of an Area Graph.
struct Route {
  double length_m = 0;
  // Indices into AreaGraph.areas and .passages, in the order the route takes.
  std::vector<int> areas;
  std::vector<int> passages;
  // From the start to the goal, in metres (map frame). Where an end lies
  // outside every area, the route goes straight from it to the nearest
  // point of an area first (and last).
  std::vector<Vec2> polyline;
};

// FindRoute's answer: a route, or why there is none.
struct RouteAnswer {
  std::optional<Route> route;
  std::string no_route_reason;
};

// Shortest routes through an Area Graph: straight lines that cross no wall,
// bending only at corners of the free space that stick into it (or at the
// ends of passages), and crossing passages anywhere along their border. The
// set-up links the corners that see each other (a visibility graph); a query
// links its two ends to the corners they see and runs A* over it.
class AreaRouter {
 public:
  // A vertex of the free space where a route may bend: where the free space
  // spans more than half a turn (between the walls `wall_a` and `wall_b`,
  // directions away from it), or an end of a passage's border.
  struct Corner {
    Vec2 at;
    bool reflex = false;
    // Whether walls bound its stretch of free space, from wall_a
    // counter-clockwise to wall_b (unit vectors, away from the corner).
    bool walled = true;
    Vec2 wall_a, wall_b;
    std::vector<int> areas;  // of its stretch
    int vertex = -1;         // in FreeSpace::vertices(), or -1 off every outline
  };

  // Throws InputError as FreeSpace does.
  explicit AreaRouter(const proto::AreaGraph& graph, const RouteSettings& settings = {});

  RouteAnswer FindRoute(const Vec2& start, const Vec2& goal) const;

  const FreeSpace& free_space() const { return space_; }
  int corner_count() const { return static_cast<int>(corners_.size()); }
  int64_t link_count() const { return static_cast<int64_t>(link_targets_.size()) / 2; }

  // The graph itself, for routes planned elsewhere (the HTML viewer): where
  // each corner is, the linked pairs (each once), and the corners that a
  // route's end in `area` is linked to when it sees them.
  const Corner& corner(int c) const { return corners_[c]; }
  // Whether a route may come to `corner` from `direction` (from the corner
  // towards the route's other point) and bend there: within its stretch, and
  // at a reflex corner on a line that does not cut it.
  static bool Admits(const Corner& corner, const Vec2& direction);
  std::vector<std::pair<int, int>> Links() const;
  std::vector<int> EndCandidates(int area) const;

 private:
  RouteSettings settings_;
  FreeSpace space_;
  std::vector<Corner> corners_;
  std::vector<std::vector<int>> area_corners_;
  std::vector<std::vector<int>> area_neighbours_;  // by passages with a border
  std::vector<int> component_;                     // of each area
  struct PassageLine {
    int area_a = 0, area_b = 0;
    std::vector<Vec2> border;  // empty when the graph gives none: not crossable
  };
  std::vector<PassageLine> passages_;
  std::vector<std::vector<int>> area_passages_;
  // Links as a compressed row list: corner c links to link_targets_[i] at
  // length link_lengths_[i] for i in [link_offsets_[c], link_offsets_[c + 1]).
  std::vector<int> link_offsets_;
  std::vector<int> link_targets_;
  std::vector<double> link_lengths_;

  void FindCorners(const proto::AreaGraph& graph);
  void LinkCorners();
  // Areas at most `hops` passages from `area` (itself included).
  std::vector<int> AreasWithin(int area, int hops) const;

  // Whether the segment from `point` (in `area`) to `to` meets one of the
  // area's passage borders: a segment that leaves the area must.
  bool LeavesThroughAPassage(const Vec2& point, int area, const Vec2& to) const;
  // The same from a corner, through a passage of any of its areas.
  bool LeavesThroughAPassage(const Corner& from, const Vec2& to) const;
  static bool ShareAnArea(const Corner& a, const Corner& b);
  // The corners that `point` (in `area`, StrictlyInside it when `inside`)
  // sees, with their distances.
  std::vector<std::pair<int, double>> VisibleCorners(const Vec2& point, int area,
                                                     bool inside) const;
  // An end of a route: where it enters the free space, its area, and
  // whether it lies strictly inside.
  struct End {
    Vec2 at;
    int area = -1;
    bool inside = false;
  };
  std::optional<std::vector<Vec2>> ShortestPolyline(const End& start, const End& goal) const;
  void Describe(Route* route) const;
};

}  // namespace areagraph
