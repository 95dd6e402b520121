#include "stages/clean/outlier_removal.h"

#include <algorithm>
#include <cmath>

#include "stages/clean/outlier_candidates.h"
#include "stages/geometry/cell_states.h"

namespace areagraph {
namespace {

// The 8 neighbours in order around the cell.
constexpr int kRingCol[8] = {-1, 0, 1, 1, 1, 0, -1, -1};
constexpr int kRingRow[8] = {-1, -1, -1, 0, 1, 1, 1, 0};

bool CanFree(const CellStates& grid, int col, int row) {
  if (grid.At(col, row) != proto::CELL_OCCUPIED) return false;
  bool free[8];
  int free_count = 0;
  for (int k = 0; k < 8; ++k) {
    const proto::CellState state = grid.At(col + kRingCol[k], row + kRingRow[k]);
    if (state == proto::CELL_UNKNOWN) return false;
    free[k] = state == proto::CELL_FREE;
    free_count += free[k];
  }
  if (free_count == 8) return true;
  int runs = 0;
  for (int k = 0; k < 8; ++k) runs += free[k] && !free[(k + 7) % 8];
  return runs == 1;
}

}  // namespace

double StraightWallScore(int neighbors) {
  // Distances along the line: 0 (the point), then 1, 1, 2, 2, 3, 3, ...
  double sum = 0;
  for (int i = 1; i < neighbors; ++i) {
    const double distance = (i + 1) / 2;
    sum += distance * distance;
  }
  return sum / neighbors;
}

std::vector<int> RemoveOutlierCells(std::string& cells, int width, int height, int neighbors,
                                    double percent) {
  const OccupiedRows occupied(cells, width, height);
  if (occupied.count() < 2 || percent <= 0) return {};
  // CGAL 5.5 averages over neighbors + 1 points (the point itself first); a
  // tiny margin so that points exactly as dense as a straight wall stay.
  const double min_score = StraightWallScore(neighbors + 1) * (1 + 1e-9);
  // remove_outliers compares scores with the square of threshold_distance.
  const double threshold = std::sqrt(min_score);
  // Each of these scores at or above the threshold exactly as CGAL's
  // remove_outliers scores it among all occupied cells (integer squared
  // distances, summed in any order to the same double; compared with CGAL
  // itself in tests/stages/clean/outlier_candidates_test.cc). Running
  // remove_outliers on their neighbourhoods as well only confirmed that, for
  // most of ag-clean's instructions.
  std::vector<OutlierCandidate> outliers =
      FindOutlierCandidates(occupied, neighbors, threshold * threshold);
  // At most `percent` % of all occupied cells, the highest scores first, as
  // remove_outliers counts them (ties go to the earlier cell).
  const size_t keep = size_t(double(occupied.count()) * ((100.0 - percent) / 100.0));
  const size_t most = size_t(occupied.count()) - keep;
  if (outliers.size() > most) {
    std::stable_sort(
        outliers.begin(), outliers.end(),
        [](const OutlierCandidate& a, const OutlierCandidate& b) { return a.score > b.score; });
    outliers.resize(most);
    std::sort(outliers.begin(), outliers.end(),
              [](const OutlierCandidate& a, const OutlierCandidate& b) { return a.cell < b.cell; });
  }

  const CellStates grid(cells, width, height);
  std::vector<int> removed;
  for (const OutlierCandidate& outlier : outliers) {
    if (CanFree(grid, outlier.cell % width, outlier.cell / width)) {
      cells[outlier.cell] = proto::CELL_FREE;
      removed.push_back(outlier.cell);
    }
  }
  return removed;
}

}  // namespace areagraph
