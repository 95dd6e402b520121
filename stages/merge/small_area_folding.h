#pragma once

#include <cstdint>
#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/merge/area_assignment.h"
#include "stages/merge/area_raster.h"

namespace areagraph {

// Folds areas with fewer than `min_cells` cells into a neighbour, smallest
// first (ties: the lower index): into one that shares a graph vertex and a
// border (the longest border), else the one with the longest border, else
// (no cells at all) the biggest that shares a vertex; an area with none of
// these stays. Updates `plan` and `raster` as if each fold had been applied
// at once, but keeps folded areas in a union-find and relabels the raster
// once at the end: a fold costs its area's bounding box, not the whole map
// (thousands of folds on a cluttered 2000 x 2000 map took minutes).
// Areas marked in `kept` (by index; may be empty) are never folded away,
// though others may fold into them (KeptSmallAreas).
void FoldSmallAreas(const proto::CutGraph& graph, int64_t min_cells, AreaPlan* plan,
                    AreaRaster* raster, const std::vector<bool>& kept = {});

}  // namespace areagraph
