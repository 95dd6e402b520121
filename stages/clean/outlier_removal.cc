#include "stages/clean/outlier_removal.h"

#include "stages/clean/outlier_points.h"
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
  std::vector<int> occupied;
  std::vector<Eigen::Vector2d> centres;
  for (int index = 0; index < width * height; ++index) {
    if (cells[index] != proto::CELL_OCCUPIED) continue;
    occupied.push_back(index);
    centres.push_back(CellCentre(index % width, index / width));
  }
  if (occupied.size() < 2) return {};
  // A tiny margin so that points exactly as dense as a straight wall stay.
  const double min_score = StraightWallScore(neighbors) * (1 + 1e-9);
  const std::vector<int> outliers = FindOutlierPoints(centres, neighbors, percent, min_score);

  const CellStates grid(cells, width, height);
  std::vector<int> removed;
  for (const int point : outliers) {
    const int index = occupied[point];
    if (CanFree(grid, index % width, index / width)) {
      cells[index] = proto::CELL_FREE;
      removed.push_back(index);
    }
  }
  return removed;
}

}  // namespace areagraph
