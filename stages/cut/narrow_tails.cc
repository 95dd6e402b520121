#include "stages/cut/narrow_tails.h"

#include <algorithm>
#include <cmath>

#include "stages/cut/width_estimate.h"
#include "stages/geometry/corridor_shape.h"

namespace areagraph {
namespace {

struct Sample {
  PathPosition position;
  double arc;
  double clearance;
};

// The piece's ends and the path vertices between them, in path order.
std::vector<Sample> SamplesOf(const EdgeTrack& track, const EdgePiece& piece) {
  std::vector<Sample> samples{
      {piece.begin, track.ArcAt(piece.begin), track.ClearanceAt(piece.begin)}};
  for (int i = piece.begin.segment + 1; i <= piece.end.segment; ++i) {
    const PathPosition at = track.AtVertex(i);
    if (track.ArcAt(at) <= samples.back().arc) continue;
    samples.push_back({at, track.ArcAt(at), track.ClearanceAt(at)});
  }
  if (track.ArcAt(piece.end) > samples.back().arc) {
    samples.push_back({piece.end, track.ArcAt(piece.end), track.ClearanceAt(piece.end)});
  }
  return samples;
}

// Where the tail of a piece begins, with `samples` running from the room to
// the dead end; -1 when the piece has no narrow tail.
int TailStart(const std::vector<Sample>& samples, double resolution_m) {
  const int n = static_cast<int>(samples.size());
  double widest = 0;
  for (const Sample& s : samples) widest = std::max(widest, s.clearance);
  const double narrow = widest / kCorridorWidthRatio;
  int first = n;
  while (first > 0 && samples[first - 1].clearance <= narrow) --first;
  if (first == 0 || first == n) return -1;
  std::vector<double> tail;
  for (int k = first; k < n; ++k) tail.push_back(samples[k].clearance);
  std::nth_element(tail.begin(), tail.begin() + tail.size() / 2, tail.end());
  const double typical = tail[tail.size() / 2];
  // Clearances (px) are half the free width.
  const double spread = SteadyWidthSpreadM(2 * typical * resolution_m) / (2 * resolution_m);
  int start = first;
  while (start < n && samples[start].clearance > typical + spread) ++start;
  if (start >= n - 1) return -1;
  // The free space goes on past the dead end by about its clearance.
  const double length =
      std::abs(samples[n - 1].arc - samples[start].arc) + samples[n - 1].clearance;
  // Long like a corridor; the tail keeps within the steady spread of its
  // typical width, which stands for its widest.
  if (Elongation(2 * typical, length * 2 * typical) < kCorridorElongation) return -1;
  return start;
}

}  // namespace

void CutNarrowTails(const EdgeTrack& track, bool source_is_dead_end, bool target_is_dead_end,
                    double resolution_m, std::vector<EdgePiece>* pieces) {
  if (target_is_dead_end && pieces->back().room >= 0) {
    const std::vector<Sample> samples = SamplesOf(track, pieces->back());
    const int start = TailStart(samples, resolution_m);
    if (start >= 0) {
      const PathPosition cut = samples[start].position;
      pieces->back().end = cut;
      pieces->push_back({cut, track.End(), -1});
    }
  }
  if (source_is_dead_end && pieces->front().room >= 0) {
    std::vector<Sample> samples = SamplesOf(track, pieces->front());
    std::reverse(samples.begin(), samples.end());
    const int start = TailStart(samples, resolution_m);
    if (start >= 0) {
      const PathPosition cut = samples[start].position;
      pieces->front().begin = cut;
      pieces->insert(pieces->begin(), {track.Start(), cut, -1});
    }
  }
}

}  // namespace areagraph
