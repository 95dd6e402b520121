#include "stages/geometry/obstacle_sites.h"

#include "stages/geometry/cell_states.h"

namespace areagraph {

std::vector<int> ObstacleSiteCells(const std::string& cells, int width, int height) {
  const CellStates grid(cells, width, height);
  std::vector<int> sites;
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) {
      if (!grid.IsFree(col, row) && grid.TouchesFree(col, row)) {
        sites.push_back(grid.Index(col, row));
      }
    }
  }
  return sites;
}

std::vector<Eigen::Vector2d> ObstacleSites(const std::string& cells, int width, int height) {
  std::vector<Eigen::Vector2d> centres;
  for (const int index : ObstacleSiteCells(cells, width, height)) {
    centres.push_back(CellCentre(index % width, index / width));
  }
  return centres;
}

}  // namespace areagraph
