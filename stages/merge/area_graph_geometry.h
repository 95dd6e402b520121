#pragma once

#include <functional>

#include "proto/artifacts.pb.h"
#include "proto/pipeline_options.pb.h"
#include "stages/merge/area_assignment.h"
#include "stages/merge/area_raster.h"

namespace areagraph {

// Adds the areas and passages of the final raster to `out` (whose frame is
// set): the raster becomes a planar partition (BuildPlanarPartition), small
// holes go and all borders are simplified together (SimplifiedOutlines with
// merge.outline_tolerance_m and merge.min_hole_m2), so every area's polygon
// is made of borders it shares with its neighbours. The passages found at
// graph vertices (FindPassages) are put on the borders they open
// (PlacePassagesOnBorders): their end points are vertices of both areas.
// With merge pass OPEN_BORDER_PASSAGES, every other border between two areas
// that a body fits across (the graph's min_clearance_m, prune.min_clearance_m)
// gets a passage too (OpenBorderPassages).
// Areas without cells are left out; ids are consecutive. `labels_done` is
// called once raster.labels is read no more (see SimplifiedOutlines), and
// before the plan's kinds are: it may still set them.
void AddAreasAndPassages(const proto::CutGraph& graph, const AreaPlan& plan,
                         const AreaRaster& raster, const proto::MergeOptions& options,
                         proto::AreaGraph* out, const std::function<void()>& labels_done = {});

}  // namespace areagraph
