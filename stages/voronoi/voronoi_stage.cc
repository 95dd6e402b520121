#include "stages/voronoi/voronoi_stage.h"

#include <algorithm>

#include "common/error.h"
#include "stages/common/stage_info.h"
#include "stages/common/voronoi_arrays.h"
#include "stages/geometry/cell_states.h"
#include "stages/geometry/obstacle_sites.h"
#include "stages/voronoi/voronoi_builder.h"

namespace areagraph {

proto::VoronoiDiagram ComputeVoronoiStage(const proto::CleanedMap& map,
                                          const proto::VoronoiOptions& /*options: none today*/) {
  const int width = map.frame().width_px();
  const int height = map.frame().height_px();
  CheckCellStates(map.cells(), width, height);
  if (std::none_of(map.cells().begin(), map.cells().end(),
                   [](char cell) { return cell == proto::CELL_FREE; })) {
    throw InputError("the map has no free space");
  }
  std::vector<Eigen::Vector2d> sites = ObstacleSites(map.cells(), width, height);
  if (sites.empty()) throw InputError("the map has no obstacle cells next to free space");

  SiteTriangulationPtr triangulation;
  proto::VoronoiDiagram diagram = BuildVoronoiDiagram(sites, {}, &triangulation);
  if (VoronoiVertexCount(diagram) == 0) {
    throw InputError("the map has too few obstacle cells for a Voronoi diagram (" +
                     std::to_string(sites.size()) + ", all on one line)");
  }
  // prune triangulates the diagram's sites again for its boundary shape; in
  // this process it takes this one.
  KeepSiteTriangulation(std::move(triangulation), std::move(sites));
  diagram.set_format_version(kVoronoiDiagramFormatVersion);
  *diagram.mutable_frame() = map.frame();
  return diagram;
}

}  // namespace areagraph
