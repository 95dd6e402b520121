#include "stages/match/join_undoing.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>
#include <utility>

#include "stages/common/map_frame.h"
#include "stages/common/skipped_passes.h"
#include "stages/geometry/polygon_split.h"
#include "stages/match/border_rings.h"
#include "stages/match/graph_assembly.h"
#include "stages/match/passage_cutting.h"
#include "stages/match/ring_pinches.h"

namespace areagraph {
namespace {

using Point = BorderPoint;

// The length of a cut (`chain`) through an area with rings `joined`, leaving
// out the stretches that run within `margin_m` of those rings all along:
// where noise moved a wall by a cell, the previous border runs beside the
// new one and the cut follows it, which is no longer opening.
double CutLengthOffWalls(const std::vector<Point>& chain, const std::vector<BorderRing>& joined,
                         double margin_m) {
  double length = 0;
  for (size_t i = 0; i + 1 < chain.size(); ++i) {
    const Point& a = chain[i];
    const Point& b = chain[i + 1];
    const double segment = std::sqrt(SquaredDistance(a, b));
    const int samples = 1 + static_cast<int>(std::ceil(segment / 0.025));
    bool along_wall = margin_m > 0;
    for (int k = 0; k <= samples && along_wall; ++k) {
      const double t = static_cast<double>(k) / samples;
      const Point p{a.first + t * (b.first - a.first), a.second + t * (b.second - a.second)};
      along_wall = DistanceToRings(p, joined) <= margin_m;
    }
    if (!along_wall) length += segment;
  }
  return length;
}

// Where a cut vertex p lies on the border edge u-v of the joined area.
struct BorderInsertion {
  Point u, v, p;
};

// The longest stretch of shared border of two pieces: the edges of `a`
// whose reverse `b` holds, chained in `a`'s direction (the two can share
// more than one stretch where the cut runs along a wall).
std::vector<Point> SharedChain(const std::vector<BorderRing>& a, const std::vector<BorderRing>& b) {
  std::set<std::pair<Point, Point>> b_edges;
  for (const auto& ring : b) {
    for (size_t i = 0; i < ring.size(); ++i) b_edges.insert({ring[i], ring[(i + 1) % ring.size()]});
  }
  std::map<Point, Point> next;
  std::set<Point> ends;
  for (const auto& ring : a) {
    for (size_t i = 0; i < ring.size(); ++i) {
      const Point& p = ring[i];
      const Point& q = ring[(i + 1) % ring.size()];
      if (b_edges.count({q, p}) == 0) continue;
      if (!next.emplace(p, q).second) return {};
      ends.insert(q);
    }
  }
  std::vector<Point> longest;
  double longest_m = 0;
  for (const auto& [start, unused] : next) {
    if (ends.count(start) > 0) continue;
    std::vector<Point> chain = {start};
    double length = 0;
    for (auto it = next.find(start); it != next.end() && chain.size() <= next.size();
         it = next.find(it->second)) {
      length += std::sqrt(SquaredDistance(chain.back(), it->second));
      chain.push_back(it->second);
    }
    if (length > longest_m) {
      longest_m = length;
      longest = std::move(chain);
    }
  }
  return longest;
}

// Adds the cut vertices to the rings (metres and pixels, vertex for vertex)
// of an area that shares a border edge with the joined area: the edge v-u of
// the insertion u-v gets p. False when the pixel rings do not pair up.
bool InsertCutVertices(const std::vector<BorderInsertion>& insertions,
                       const MapTransform& transform, proto::Area* area) {
  std::map<std::pair<Point, Point>, std::vector<Point>> on_edge;  // (v, u) -> points
  for (const BorderInsertion& insertion : insertions) {
    on_edge[{insertion.v, insertion.u}].push_back(insertion.p);
  }
  const auto rings_m = Rings(area->polygon_m());
  const auto rings_px = Rings(area->polygon_px());
  bool changed = false;
  std::vector<BorderRing> new_m, new_px;
  for (size_t r = 0; r < rings_m.size(); ++r) {
    const std::vector<Point>& ring = rings_m[r];
    std::vector<Point> out_m, out_px;
    for (size_t i = 0; i < ring.size(); ++i) {
      const Point& from = ring[i];
      const Point& to = ring[(i + 1) % ring.size()];
      out_m.push_back(from);
      if (r < rings_px.size() && rings_px[r].size() == ring.size())
        out_px.push_back(rings_px[r][i]);
      const auto found = on_edge.find({from, to});
      if (found == on_edge.end()) continue;
      if (r >= rings_px.size() || rings_px[r].size() != ring.size()) return false;
      std::vector<Point> points = found->second;
      std::sort(points.begin(), points.end(), [&](const Point& a, const Point& b) {
        return SquaredDistance(a, from) < SquaredDistance(b, from);
      });
      for (const Point& p : points) {
        out_m.push_back(p);
        const Eigen::Vector2d px = transform.WorldToPixel({p.first, p.second});
        out_px.push_back({px.x(), px.y()});
      }
      changed = true;
    }
    new_m.push_back(std::move(out_m));
    new_px.push_back(std::move(out_px));
  }
  if (!changed) return true;
  *area->mutable_polygon_m() = ToPolygon(new_m);
  *area->mutable_polygon_px() = ToPolygon(new_px);
  return true;
}

// One join cut apart (see SplitJoinedAreas), on `areas` and `passages`.
// `kept` is the previous area whose id the joined area holds.
// `options`: whether a cut may cross a passage's border
// (UNDO_JOINS_ACROSS_PASSAGES) and the wall margin (CutLengthOffWalls).
// `robot_width_m`: the least opening (a passage narrower than a robot is
// where two polygons barely touched, not how wide the door was) and the
// least stretch of a cut passage that stays one.
bool SplitOne(const proto::AreaGraph& previous, int joined_index, int swallowed, int kept,
              const proto::MatchOptions& options, double robot_width_m,
              const MapTransform& transform, std::vector<proto::Area>& areas,
              std::vector<proto::Passage>& passages) {
  const bool cut_passages = RunsStagePass(options, proto::MatchOptions::UNDO_JOINS_ACROSS_PASSAGES);
  const double wall_margin_m = options.split_joins_wall_margin_m();
  const proto::Area& joined = areas[joined_index];
  proto::Polygon inside, rest;
  if (!SplitPolygonByGuide(joined.polygon_m(),
                           WithoutPinches(previous.areas(swallowed).polygon_m()), &inside, &rest)) {
    return false;
  }
  const auto joined_m = Rings(joined.polygon_m());
  const auto joined_px = Rings(joined.polygon_px());
  if (joined_m.size() != joined_px.size()) return false;
  std::map<Point, Point> px_of;
  for (size_t r = 0; r < joined_m.size(); ++r) {
    if (joined_m[r].size() != joined_px[r].size()) return false;
    for (size_t i = 0; i < joined_m[r].size(); ++i) px_of[joined_m[r][i]] = joined_px[r][i];
  }
  const auto inside_m = Rings(inside), rest_m = Rings(rest);
  const std::set<Point> inside_vertices = Vertices(inside_m), rest_vertices = Vertices(rest_m);
  for (const auto& [vertex, px] : px_of) {
    if (inside_vertices.count(vertex) == 0 && rest_vertices.count(vertex) == 0) return false;
  }
  // Border edges of the joined area's passages (-> passage index): a cut
  // that crosses one cuts the passage too (CutPassage), or is refused.
  std::map<std::pair<Point, Point>, int> passage_edges;
  for (size_t j = 0; j < passages.size(); ++j) {
    const proto::Passage& passage = passages[j];
    if (passage.area_a() != joined_index && passage.area_b() != joined_index) continue;
    for (int i = 0; i + 1 < passage.border_m_size(); ++i) {
      const Point a = ToBorderPoint(passage.border_m(i)),
                  b = ToBorderPoint(passage.border_m(i + 1));
      passage_edges[{a, b}] = static_cast<int>(j);
      passage_edges[{b, a}] = static_cast<int>(j);
    }
  }
  std::map<int, std::vector<Point>> crossed;  // passage index -> cut points on its border
  std::vector<BorderInsertion> insertions;
  std::set<Point> cut_vertices = inside_vertices;
  cut_vertices.insert(rest_vertices.begin(), rest_vertices.end());
  for (const Point& p : cut_vertices) {
    if (px_of.count(p) > 0) continue;
    for (const auto& ring : joined_m) {
      for (size_t i = 0; i < ring.size(); ++i) {
        const Point& u = ring[i];
        const Point& v = ring[(i + 1) % ring.size()];
        if (!OnSegment(p, u, v)) continue;
        const auto passage = passage_edges.find({u, v});
        if (passage != passage_edges.end()) {
          if (!cut_passages) return false;
          crossed[passage->second].push_back(p);
        }
        insertions.push_back({u, v, p});
      }
    }
  }
  const std::vector<Point> chain = SharedChain(rest_m, inside_m);
  if (chain.size() < 2) return false;

  // Everything checked on copies first; then the graph changes.
  std::vector<proto::Area> updated = areas;
  if (!insertions.empty()) {
    for (size_t j = 0; j < updated.size(); ++j) {
      if (static_cast<int>(j) == joined_index) continue;
      if (!InsertCutVertices(insertions, transform, &updated[j])) return false;
    }
  }
  auto to_px = [&](const std::vector<BorderRing>& rings) {
    std::vector<BorderRing> px = rings;
    for (auto& ring : px) {
      for (Point& p : ring) {
        const auto found = px_of.find(p);
        if (found != px_of.end()) {
          p = found->second;
        } else {
          const Eigen::Vector2d pixel = transform.WorldToPixel({p.first, p.second});
          p = {pixel.x(), pixel.y()};
        }
      }
    }
    return ToPolygon(px);
  };
  proto::Area piece;
  piece.set_kind(joined.kind());
  *piece.mutable_polygon_m() = inside;
  *piece.mutable_polygon_px() = to_px(inside_m);
  double area_m2 = 0;
  AreaAndCentroid(inside_m, &area_m2, piece.mutable_centroid_m());
  piece.set_area_m2(area_m2);
  proto::Area& remainder = updated[joined_index];
  *remainder.mutable_polygon_m() = rest;
  *remainder.mutable_polygon_px() = to_px(rest_m);
  AreaAndCentroid(rest_m, &area_m2, remainder.mutable_centroid_m());
  remainder.set_area_m2(area_m2);
  const int piece_index = static_cast<int>(updated.size());
  updated.push_back(std::move(piece));

  std::vector<proto::Passage> moved;
  for (size_t j = 0; j < passages.size(); ++j) {
    const auto cut = crossed.find(static_cast<int>(j));
    if (cut == crossed.end()) {
      moved.push_back(passages[j]);
      continue;
    }
    std::vector<proto::Passage> pieces = CutPassage(passages[j], cut->second, robot_width_m);
    if (pieces.empty()) return false;
    moved.insert(moved.end(), pieces.begin(), pieces.end());
  }
  for (proto::Passage& passage : moved) {
    if (passage.area_a() != joined_index && passage.area_b() != joined_index) continue;
    bool in_piece = passage.border_m_size() > 0;
    for (const proto::Point2& p : passage.border_m()) {
      in_piece = in_piece && inside_vertices.count(ToBorderPoint(p)) > 0;
    }
    bool in_rest = passage.border_m_size() > 0;
    for (const proto::Point2& p : passage.border_m()) {
      in_rest = in_rest && rest_vertices.count(ToBorderPoint(p)) > 0;
    }
    if (passage.border_m_size() == 0) {
      // An older graph's passage: by the piece nearer to where it crosses.
      const Point at = ToBorderPoint(passage.point_m());
      in_piece = DistanceToRings(at, inside_m) < DistanceToRings(at, rest_m);
      in_rest = !in_piece;
    }
    if (in_piece == in_rest) return false;  // its border runs along the cut
    if (!in_piece) continue;
    if (passage.area_a() == joined_index) passage.set_area_a(piece_index);
    if (passage.area_b() == joined_index) passage.set_area_b(piece_index);
  }
  // The passage between the two pieces, rest on the left of its border.
  proto::Passage between;
  between.set_area_a(joined_index);
  between.set_area_b(piece_index);
  const bool rest_counterclockwise = [&] {
    double twice = 0;
    for (size_t i = 0; i < rest_m[0].size(); ++i) {
      const Point& p = rest_m[0][i];
      const Point& q = rest_m[0][(i + 1) % rest_m[0].size()];
      twice += p.first * q.second - q.first * p.second;
    }
    return twice > 0;
  }();
  std::vector<Point> border = chain;
  if (!rest_counterclockwise) std::reverse(border.begin(), border.end());
  for (const Point& p : border) SetBorderPoint(p, between.add_border_m());
  SetBorderPoint(border.front(), between.mutable_segment_m()->mutable_a());
  SetBorderPoint(border.back(), between.mutable_segment_m()->mutable_b());
  SetBorderPoint(border[border.size() / 2], between.mutable_point_m());
  between.set_width_m(std::sqrt(SquaredDistance(border.front(), border.back())));
  // The previous passage between the two; the opening it was must not have
  // grown much (a wall removed is a real join, not noise).
  // Without a previous passage (UNDO_JOINS_WITHOUT_PASSAGE) the opening
  // counts as the least one.
  double opening_m = robot_width_m;
  for (const proto::Passage& old : previous.passages()) {
    const bool between_them = (old.area_a() == kept && old.area_b() == swallowed) ||
                              (old.area_a() == swallowed && old.area_b() == kept);
    if (!between_them) continue;
    *between.mutable_point_m() = old.point_m();
    between.set_width_m(old.width_m());
    double border_m = 0;
    for (int i = 0; i + 1 < old.border_m_size(); ++i) {
      border_m += std::sqrt(
          SquaredDistance(ToBorderPoint(old.border_m(i)), ToBorderPoint(old.border_m(i + 1))));
    }
    opening_m = std::max({old.width_m(), border_m, robot_width_m});
    break;
  }
  if (CutLengthOffWalls(chain, joined_m, wall_margin_m) > kMaxCutPerOpening * opening_m) {
    return false;
  }
  moved.push_back(std::move(between));
  areas = std::move(updated);
  passages = std::move(moved);
  return true;
}

}  // namespace

std::vector<AreaUnjoin> FindUndoableJoins(const proto::AreaGraph& previous,
                                          const std::vector<int>& ids, const AreaCells& before,
                                          const std::vector<AreaOverlap>& overlaps, double max_m2,
                                          double inside_share, bool when_id_moved,
                                          bool without_passage) {
  const std::set<int> taken(ids.begin(), ids.end());
  std::vector<int> best(previous.areas_size(), -1);
  std::vector<int64_t> best_cells(previous.areas_size(), 0);
  for (const AreaOverlap& pair : overlaps) {
    if (pair.cells > best_cells[pair.before]) {
      best[pair.before] = pair.after;
      best_cells[pair.before] = pair.cells;
    }
  }
  std::map<int, int> previous_of_id;  // stable id -> index in previous
  for (int i = 0; i < previous.areas_size(); ++i) previous_of_id[previous.areas(i).stable_id()] = i;
  std::set<std::pair<int, int>> linked;  // previous areas joined by a passage
  for (const proto::Passage& passage : previous.passages()) {
    linked.insert({passage.area_a(), passage.area_b()});
    linked.insert({passage.area_b(), passage.area_a()});
  }
  std::map<int, std::tuple<int64_t, int, int>> chosen;  // current area -> (cells, previous, kept)
  for (int b = 0; b < previous.areas_size(); ++b) {
    const int k = best[b];
    // b is joined when its id is on no area, or (when_id_moved) on another
    // area than the one that holds most of it.
    if (k < 0 || ids[k] == previous.areas(b).stable_id()) continue;
    if (!when_id_moved && taken.count(previous.areas(b).stable_id()) > 0) continue;
    if (previous.areas(b).area_m2() >= max_m2) continue;
    if (best_cells[b] < inside_share * before.cells[b] || ids[k] < 0) continue;
    const auto kept = previous_of_id.find(ids[k]);
    if (kept == previous_of_id.end()) continue;
    if (linked.count({kept->second, b}) == 0 &&
        (!without_passage ||
         !ShareBorder(previous.areas(kept->second).polygon_m(), previous.areas(b).polygon_m()))) {
      continue;
    }
    auto& entry = chosen[k];
    if (before.cells[b] > std::get<0>(entry)) entry = {before.cells[b], b, kept->second};
  }
  std::vector<AreaUnjoin> unjoins;
  for (const auto& [k, entry] : chosen) {
    if (std::get<0>(entry) > 0) unjoins.push_back({k, std::get<1>(entry), std::get<2>(entry)});
  }
  return unjoins;
}

proto::AreaGraph SplitJoinedAreas(const proto::AreaGraph& current, const proto::AreaGraph& previous,
                                  const std::vector<AreaUnjoin>& unjoins,
                                  const proto::MatchOptions& options, int* done) {
  std::vector<proto::Area> areas(current.areas().begin(), current.areas().end());
  std::vector<proto::Passage> passages(current.passages().begin(), current.passages().end());
  const MapTransform transform(current.frame());
  int count = 0;
  for (const AreaUnjoin& unjoin : unjoins) {
    if (SplitOne(previous, unjoin.area, unjoin.previous, unjoin.kept, options,
                 current.robot_width_m(), transform, areas, passages)) {
      ++count;
    }
  }
  if (done != nullptr) *done = count;
  if (count == 0) return current;
  return AssembleGraph(current, std::move(areas), std::move(passages));
}

}  // namespace areagraph
