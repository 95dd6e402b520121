#include "stages/voronoi/voronoi_stage.h"

#include <algorithm>

#include "stages/geometry/cell_states.h"
#include "stages/geometry/obstacle_sites.h"
#include "stages/voronoi/voronoi_builder.h"
#include "store/error.h"

namespace areagraph {

proto::VoronoiDiagram ComputeVoronoiStage(const proto::CleanedMap& map,
                                          const proto::VoronoiOptions& options,
                                          const std::string& map_name) {
  const std::string what = "map '" + map_name + "'";
  const int width = map.frame().width_px();
  const int height = map.frame().height_px();
  CheckCellStates(map.cells(), width, height, what);
  if (std::none_of(map.cells().begin(), map.cells().end(),
                   [](char cell) { return cell == proto::CELL_FREE; })) {
    throw InputError(what + " has no free space");
  }
  const std::vector<Eigen::Vector2d> sites = ObstacleSites(map.cells(), width, height);
  if (sites.empty()) throw InputError(what + " has no obstacle cells next to free space");

  VoronoiBuildOptions build_options;
  build_options.keep_rays = options.keep_rays();
  proto::VoronoiDiagram diagram = BuildVoronoiDiagram(sites, build_options);
  if (diagram.vertices_size() == 0) {
    throw InputError(what + " has too few obstacle cells for a Voronoi diagram (" +
                     std::to_string(sites.size()) + ", all on one line)");
  }
  diagram.set_format_version(1);
  *diagram.mutable_frame() = map.frame();
  return diagram;
}

}  // namespace areagraph
