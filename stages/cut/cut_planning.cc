#include "stages/cut/cut_planning.h"

#include <algorithm>
#include <cmath>

namespace areagraph {
namespace {

// Spacing of the samples that look for room changes along a segment (px).
constexpr double kSampleStepPx = 0.5;
// Clearances within this of the minimum count as equally narrow (px): a
// tie-break, since the sites lie on cell centres and clearances closer than
// half a cell are the grid's rounding, not a narrower spot.
constexpr double kNarrowTolerancePx = 0.5;

double Length(const EdgeTrack& track, const EdgePiece& piece) {
  return track.ArcAt(piece.end) - track.ArcAt(piece.begin);
}

// Pieces of constant room along the path.
std::vector<EdgePiece> SplitByRoom(const EdgeTrack& track,
                                   const std::function<int(const Eigen::Vector2d&)>& room_at) {
  const PointList& path = track.path();
  std::vector<int> vertex_room(path.size());
  for (size_t i = 0; i < path.size(); ++i) vertex_room[i] = room_at(path[i]);

  std::vector<EdgePiece> pieces{{track.Start(), track.End(), vertex_room[0]}};
  for (int s = 0; s < track.segment_count(); ++s) {
    if (vertex_room[s] == vertex_room[s + 1]) continue;
    const Eigen::Vector2d a = path[s], b = path[s + 1];
    const double length = (b - a).norm();
    const int samples = std::max(1, static_cast<int>(std::ceil(length / kSampleStepPx)));
    double previous_t = 0;
    int previous_room = vertex_room[s];
    for (int k = 1; k <= samples; ++k) {
      const double t = static_cast<double>(k) / samples;
      const int room = k == samples ? vertex_room[s + 1] : room_at(a + t * (b - a));
      if (room != previous_room) {
        double low = previous_t, high = t;
        for (int step = 0; step < 40 && (high - low) * length > 1e-3; ++step) {
          const double mid = 0.5 * (low + high);
          (room_at(a + mid * (b - a)) == previous_room ? low : high) = mid;
        }
        const PathPosition cut = track.Normalized({s, high});
        pieces.back().end = cut;
        pieces.push_back({cut, track.End(), room});
        previous_room = room;
      }
      previous_t = t;
    }
  }
  return pieces;
}

// Joins pieces [first, last] into one piece of `room`.
void JoinPieces(std::vector<EdgePiece>* pieces, int first, int last, int room) {
  (*pieces)[first].end = (*pieces)[last].end;
  (*pieces)[first].room = room;
  pieces->erase(pieces->begin() + first + 1, pieces->begin() + last + 1);
}

// Rule 3: doorways. Returns true when something changed.
bool FoldOneDoorway(const EdgeTrack& track, double room_width_px, std::vector<EdgePiece>* pieces) {
  for (int k = 1; k + 1 < static_cast<int>(pieces->size()); ++k) {
    EdgePiece& piece = (*pieces)[k];
    if (piece.room >= 0 || Length(track, piece) >= room_width_px) continue;
    EdgePiece& before = (*pieces)[k - 1];
    EdgePiece& after = (*pieces)[k + 1];
    if (before.room < 0 || after.room < 0) continue;
    if (before.room == after.room) {
      JoinPieces(pieces, k - 1, k + 1, before.room);
    } else {
      const PathPosition narrowest = NarrowestPosition(track, piece.begin, piece.end);
      before.end = narrowest;
      after.begin = narrowest;
      pieces->erase(pieces->begin() + k);
    }
    return true;
  }
  return false;
}

// Whether the cut at `at` lies on a line the cut closed.
bool OnClosedLine(const EdgeTrack& track, const PathPosition& at, const ClosedLines* lines) {
  return lines != nullptr && lines->Near(track.PointAt(at));
}

// Rule 2 for the pieces at dead ends. Returns true when something changed.
bool DropOneShortTip(const EdgeTrack& track, bool source_is_dead_end, bool target_is_dead_end,
                     double room_width_px, const ClosedLines* closed_lines,
                     std::vector<EdgePiece>* pieces) {
  const int n = static_cast<int>(pieces->size());
  if (n < 2) return false;
  if (source_is_dead_end && Length(track, pieces->front()) < room_width_px &&
      !OnClosedLine(track, pieces->front().end, closed_lines)) {
    JoinPieces(pieces, 0, 1, (*pieces)[1].room);
    return true;
  }
  if (target_is_dead_end && Length(track, pieces->back()) < room_width_px &&
      !OnClosedLine(track, pieces->back().begin, closed_lines)) {
    JoinPieces(pieces, n - 2, n - 1, (*pieces)[n - 2].room);
    return true;
  }
  return false;
}

// A position `distance` further along the path than `from` (clamped).
PathPosition Advance(const EdgeTrack& track, const PathPosition& from, double distance) {
  const double target = track.ArcAt(from) + distance;
  if (target >= track.length()) return track.End();
  if (target <= 0) return track.Start();
  int s = from.segment;
  const PointList& path = track.path();
  double arc = track.ArcAt({s, 0});
  for (; s < track.segment_count(); ++s) {
    const double length = (path[s + 1] - path[s]).norm();
    if (arc + length >= target)
      return track.Normalized({s, length > 0 ? (target - arc) / length : 0});
    arc += length;
  }
  return track.End();
}

PathPosition Retreat(const EdgeTrack& track, const PathPosition& from, double distance) {
  const double target = track.ArcAt(from) - distance;
  if (target <= 0) return track.Start();
  const PointList& path = track.path();
  for (int s = from.segment; s >= 0; --s) {
    const double start = track.ArcAt({s, 0});
    if (start <= target) {
      const double length = (path[s + 1] - path[s]).norm();
      return track.Normalized({s, length > 0 ? (target - start) / length : 0});
    }
  }
  return track.Start();
}

// Rule 4: move cuts between a room and a room-less stretch to its narrowest point.
void MoveCutsToNarrowest(const EdgeTrack& track, double room_width_px,
                         std::vector<EdgePiece>* pieces) {
  const int n = static_cast<int>(pieces->size());
  for (int k = 0; k + 1 < n; ++k) {
    EdgePiece& before = (*pieces)[k];
    EdgePiece& after = (*pieces)[k + 1];
    if ((before.room < 0) == (after.room < 0)) continue;
    const bool roomless_after = after.room < 0;
    const EdgePiece& roomless = roomless_after ? after : before;
    // A stretch between two cuts is searched from both ends: half each.
    const bool cut_on_both_ends = roomless_after ? k + 2 < n : k > 0;
    const double reach =
        std::min(room_width_px, Length(track, roomless) * (cut_on_both_ends ? 0.5 : 1.0));
    PathPosition moved;
    if (roomless_after) {
      moved = NarrowestPosition(track, after.begin, Advance(track, after.begin, reach));
    } else {
      moved = NarrowestPosition(track, Retreat(track, before.end, reach), before.end);
    }
    before.end = moved;
    after.begin = moved;
  }
}

}  // namespace

PathPosition NarrowestPosition(const EdgeTrack& track, const PathPosition& from,
                               const PathPosition& to) {
  struct Candidate {
    PathPosition position;
    double arc;
    double clearance;
  };
  std::vector<Candidate> candidates{{from, track.ArcAt(from), track.ClearanceAt(from)}};
  for (int i = from.segment + 1; i <= to.segment; ++i) {
    const PathPosition at = track.AtVertex(i);
    if (track.ArcAt(at) <= candidates.front().arc) continue;
    candidates.push_back({at, track.ArcAt(at), track.ClearanceAt(at)});
  }
  if (track.ArcAt(to) > candidates.back().arc) {
    candidates.push_back({to, track.ArcAt(to), track.ClearanceAt(to)});
  }
  size_t best = 0;
  for (size_t i = 1; i < candidates.size(); ++i) {
    if (candidates[i].clearance < candidates[best].clearance) best = i;
  }
  const double limit = candidates[best].clearance + kNarrowTolerancePx;
  size_t first = best, last = best;
  while (first > 0 && candidates[first - 1].clearance <= limit) --first;
  while (last + 1 < candidates.size() && candidates[last + 1].clearance <= limit) ++last;
  const double middle = 0.5 * (candidates[first].arc + candidates[last].arc);
  size_t chosen = first;
  for (size_t i = first; i <= last; ++i) {
    if (std::abs(candidates[i].arc - middle) < std::abs(candidates[chosen].arc - middle))
      chosen = i;
  }
  return candidates[chosen].position;
}

std::vector<EdgePiece> PlanEdgeCuts(const EdgeTrack& track, bool source_is_dead_end,
                                    bool target_is_dead_end, double room_width_px,
                                    const std::function<int(const Eigen::Vector2d&)>& room_at,
                                    const ClosedLines* closed_lines) {
  std::vector<EdgePiece> pieces = SplitByRoom(track, room_at);
  if (pieces.size() == 1) return pieces;

  const bool closed_cut = std::any_of(
      pieces.begin() + 1, pieces.end(),
      [&](const EdgePiece& piece) { return OnClosedLine(track, piece.begin, closed_lines); });
  if ((source_is_dead_end || target_is_dead_end) && track.length() < room_width_px && !closed_cut) {
    const int room =
        source_is_dead_end && !target_is_dead_end ? pieces.back().room : pieces.front().room;
    return {{track.Start(), track.End(), room}};
  }
  while (DropOneShortTip(track, source_is_dead_end, target_is_dead_end, room_width_px, closed_lines,
                         &pieces) ||
         FoldOneDoorway(track, room_width_px, &pieces)) {
  }
  MoveCutsToNarrowest(track, room_width_px, &pieces);
  // Cuts that landed on each other leave empty pieces; neighbours of one room merge.
  for (int k = 0; k + 1 < static_cast<int>(pieces.size());) {
    EdgePiece& piece = pieces[k];
    EdgePiece& next = pieces[k + 1];
    if (piece.room == next.room || Length(track, next) <= 1e-6) {
      JoinPieces(&pieces, k, k + 1, piece.room);
    } else if (Length(track, piece) <= 1e-6) {
      JoinPieces(&pieces, k, k + 1, next.room);
    } else {
      ++k;
    }
  }
  return pieces;
}

}  // namespace areagraph
