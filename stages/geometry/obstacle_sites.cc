#include "stages/geometry/obstacle_sites.h"

#include "proto/artifacts.pb.h"
#include "stages/geometry/cell_states.h"
#include "stages/geometry/near_free_mask.h"

namespace areagraph {

std::vector<int> ObstacleSiteCells(const std::string& cells, int width, int height) {
  const std::vector<uint8_t> near_free = NearFreeMask(cells, width, height);
  std::vector<int> sites;
  const int count = width * height;
  for (int index = 0; index < count; ++index) {
    if (near_free[index] && cells[index] != proto::CELL_FREE) sites.push_back(index);
  }
  return sites;
}

std::vector<Eigen::Vector2d> ObstacleSites(const std::string& cells, int width, int height) {
  const std::vector<int> site_cells = ObstacleSiteCells(cells, width, height);
  std::vector<Eigen::Vector2d> centres;
  centres.reserve(site_cells.size());
  for (const int index : site_cells) centres.push_back(CellCentre(index % width, index / width));
  return centres;
}

}  // namespace areagraph
