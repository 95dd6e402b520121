#pragma once

#include <string>

#include "proto/artifacts.pb.h"
#include "proto/pipeline_options.pb.h"

namespace areagraph {

// The ag-clean computation: outlier removal (RemoveOutlierCells), then
// furniture removal (RemoveFurniture), on a copy of the map's cells. Sets
// format_version and frame. Throws OptionsError for bad options and
// InputError for a malformed grid or a map without free space or without
// obstacle cells.
proto::CleanedMap CleanGridMap(const proto::GridMap& map, const proto::CleanOptions& options);

}  // namespace areagraph
