#pragma once

#include <string>

#include "proto/artifacts.pb.h"
#include "proto/pipeline_options.pb.h"

namespace areagraph {

// The ag-voronoi computation: the Voronoi diagram (see BuildVoronoiDiagram)
// of the cleaned map's ObstacleSites, with format_version and frame set.
// Throws InputError when the grid is malformed, has no free space, or has too
// few obstacle sites for a diagram.
proto::VoronoiDiagram ComputeVoronoiStage(const proto::CleanedMap& map,
                                          const proto::VoronoiOptions& options);

}  // namespace areagraph
