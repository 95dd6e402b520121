#pragma once

#include <string>

#include "proto/artifacts.pb.h"
#include "proto/pipeline_options.pb.h"
#include "stages/merge/area_raster.h"

namespace areagraph {

// ag-merge: the Area Graph. The CutGraph's edges are grouped into areas
// (AssignAreas); the areas split the map's free cells inside the boundary
// among themselves (PartitionFreeSpace), so they never overlap and each is
// one piece; cells that ag-clean freed stay out unless
// merge.cover_removed_obstacles, and free space behind gaps narrower than
// the robot's width (merge pass GROWTH_STOPS_AT_NARROW_GAPS) that no edge
// reaches stays unlabelled; areas smaller
// than merge.min_area_m2 (and areas left without cells) fold into the
// neighbour they share the longest border with. The areas' polygons are
// a planar partition of that raster, simplified without changing its
// topology, and the passages (where areas meet at graph vertices) lie on the
// borders they open (AddAreasAndPassages). When
// `raster` is given it receives the final label image. Throws InputError for
// an unusable CutGraph.
proto::AreaGraph BuildAreaGraph(const proto::CutGraph& graph, const proto::CleanedMap& map,
                                const proto::MergeOptions& options, AreaRaster* raster = nullptr);

}  // namespace areagraph
