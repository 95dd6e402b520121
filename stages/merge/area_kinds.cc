#include "stages/merge/area_kinds.h"

#include <set>

#include "stages/merge/area_shapes.h"

namespace areagraph {

void SetAreaKinds(const proto::CutGraph& graph, const AreaRaster& raster, double resolution_m,
                  AreaPlan* plan, const cv::Mat& furniture) {
  const int area_count = static_cast<int>(plan->areas.size());
  std::vector<int> exits(area_count, 0);
  for (const std::set<int>& at : AreasAtVertices(graph, *plan)) {
    if (at.size() < 2) continue;
    for (const int area : at) ++exits[area];
  }
  for (int k = 0; k < area_count; ++k) {
    AreaPlan::Area& area = plan->areas[k];
    if (!RasterShape(raster, k, resolution_m, graph.island_max_length_m(), furniture).corridor) {
      area.kind = proto::AREA_ROOM;
    } else if (exits[k] >= 2) {
      area.kind = proto::AREA_CORRIDOR;
    } else {
      area.kind = proto::AREA_DEAD_END;
    }
  }
}

}  // namespace areagraph
