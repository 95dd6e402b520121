#include "stages/clean/outlier_candidates.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "stages/geometry/parallel_ranges.h"

namespace areagraph {
namespace {

// Offsets up to this radius are visited in order of distance on a grid
// padded by as much; the few cells with fewer occupied cells that close
// search the rows in growing disks instead.
constexpr int kNear = 12;

// Cells per range on the pool: a cell costs some tens to a thousand
// instructions, the pool's start some microseconds.
constexpr size_t kParallelCells = 4096;

struct Offset {
  long delta;  // in the padded grid
  int d2;
};

// Grid offsets within kNear, nearest first; with `axes_only`, just the 5 x 5
// box and the four straight arms (enough to see that a point of a straight
// wall, or of anything denser, scores low).
std::vector<Offset> NearOffsets(long padded_width, bool axes_only) {
  struct Step {
    int dc, dr, d2;
  };
  std::vector<Step> steps;
  for (int dr = -kNear; dr <= kNear; ++dr) {
    for (int dc = -kNear; dc <= kNear; ++dc) {
      if (dc * dc + dr * dr > kNear * kNear) continue;
      const bool in_box = std::abs(dc) <= 2 && std::abs(dr) <= 2;
      if (axes_only && !in_box && dc != 0 && dr != 0) continue;
      steps.push_back({dc, dr, dc * dc + dr * dr});
    }
  }
  std::stable_sort(steps.begin(), steps.end(),
                   [](const Step& a, const Step& b) { return a.d2 < b.d2; });
  std::vector<Offset> offsets;
  offsets.reserve(steps.size());
  for (const Step& step : steps) offsets.push_back({step.dr * padded_width + step.dc, step.d2});
  return offsets;
}

// Visits `offsets` from `here` until `points` occupied cells are found:
// returns their number, the sum of their squared distances and the largest.
int NearestSum(const uint8_t* here, const std::vector<Offset>& offsets, int points, long* sum,
               int* reach2) {
  int found = 0;
  *sum = 0;
  for (const Offset& offset : offsets) {
    if (!here[offset.delta]) continue;
    *sum += offset.d2;
    *reach2 = offset.d2;
    if (++found == points) break;
  }
  return found;
}

// NearestSum over the axes' offsets (the 5 x 5 box, then the arms from 3
// to kNear cells out, farther than any cell of the box) with word
// operations: the box's rows as eight bytes each, then the arms' cells in
// order of distance. Returns the number found (at most `points`) and their
// sum; when the box alone holds `points`, the offsets decide.
int AxesNearestSum(const uint8_t* here, long padded_width, const std::vector<Offset>& axes,
                   int points, long* sum, int* reach2) {
  // Bytes 0 .. 4 of a box row are the columns -2 .. 2: low bits of each.
  constexpr uint64_t kRow = 0x0000000101010101u;
  constexpr uint64_t kOne = 0x0000000001000100u;   // columns -1 and 1
  constexpr uint64_t kFour = 0x0000000100000001u;  // columns -2 and 2
  // The sum of the bytes of a word of 0 / 1 bytes (no popcount instruction
  // in the baseline instruction set).
  auto bytes = [](uint64_t word) { return int((word * 0x0101010101010101u) >> 56); };
  int found = 0;
  long total = 0;
  int farthest = 0;
  for (int dr = -2; dr <= 2; ++dr) {
    uint64_t row;
    std::memcpy(&row, here + dr * padded_width - 2, sizeof(row));
    const int count = bytes(row & kRow);
    if (count == 0) continue;
    found += count;
    total += long(dr * dr) * count + bytes(row & kOne) + 4L * bytes(row & kFour);
    farthest = std::max(farthest, dr * dr + (row & kFour ? 4 : row & kOne ? 1 : 0));
  }
  if (found >= points) return NearestSum(here, axes, points, sum, reach2);
  for (int k = 3; k <= kNear && found < points; ++k) {
    const long down = k * padded_width;
    const int count = here[k] + here[-k] + here[down] + here[-down];
    if (count == 0) continue;
    const int take = std::min(count, points - found);
    total += long(take) * k * k;
    found += take;
    farthest = k * k;
  }
  *sum = total;
  *reach2 = farthest;
  return found;
}

// The score of an isolated cell: the nearest `points` occupied cells (or all
// of them) from disks of doubling radius.
OutlierCandidate ScoreFarCell(const OccupiedRows& occupied, int cell, int points) {
  const int col = cell % occupied.width();
  const int row = cell / occupied.width();
  const long extent = long(occupied.width()) + occupied.height();
  std::vector<long> d2s;
  for (long radius = 2 * kNear;; radius *= 2) {
    d2s.clear();
    occupied.ForEachWithin(col, row, radius * radius, [&](int, long d2) { d2s.push_back(d2); });
    if (long(d2s.size()) >= points || radius > extent) break;
  }
  const size_t used = std::min(d2s.size(), size_t(points));
  std::nth_element(d2s.begin(), d2s.begin() + (used - 1), d2s.end());
  double sum = 0;
  long reach2 = 0;
  for (size_t i = 0; i < used; ++i) {
    sum += double(d2s[i]);
    reach2 = std::max(reach2, d2s[i]);
  }
  return {cell, sum / double(used), int(reach2)};
}

}  // namespace

std::vector<OutlierCandidate> FindOutlierCandidates(const OccupiedRows& occupied, int neighbors,
                                                    double threshold_score) {
  const int width = occupied.width();
  const int points = neighbors + 1;
  const long padded_width = width + 2 * kNear;
  const std::vector<int> cells = occupied.Cells();
  std::vector<uint8_t> padded(size_t(padded_width) * (occupied.height() + 2 * kNear), 0);
  const long origin = kNear * padded_width + kNear;
  for (const int cell : cells) padded[origin + (cell / width) * padded_width + cell % width] = 1;
  const std::vector<Offset> axes = NearOffsets(padded_width, true);
  const std::vector<Offset> near = NearOffsets(padded_width, false);

  // Every cell is scored alone: ranges of cells on the pool, their
  // candidates joined in range order (row-major, as one pass gives them).
  return ConcatRanges<OutlierCandidate>(
      cells.size(), kParallelCells, [&](size_t begin, size_t end) {
        std::vector<OutlierCandidate> found;
        for (size_t i = begin; i < end; ++i) {
          const int cell = cells[i];
          const uint8_t* here =
              padded.data() + origin + (cell / width) * padded_width + cell % width;
          long sum = 0;
          int reach2 = 0;
          // Any `points` occupied cells bound the score from above: when the
          // nearest ones along the axes already score low, the cell is no outlier.
          if (AxesNearestSum(here, padded_width, axes, points, &sum, &reach2) == points &&
              double(sum) / points < threshold_score) {
            continue;
          }
          const OutlierCandidate candidate =
              NearestSum(here, near, points, &sum, &reach2) == points
                  ? OutlierCandidate{cell, double(sum) / points, reach2}
                  : ScoreFarCell(occupied, cell, points);
          if (candidate.score >= threshold_score) found.push_back(candidate);
        }
        return found;
      });
}

}  // namespace areagraph
