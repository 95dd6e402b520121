#pragma once

#include <cstdint>
#include <string>

#include "areagraph_lcm/area_graph_diff_t.hpp"
#include "areagraph_lcm/area_graph_t.hpp"
#include "areagraph_lcm/grid_map_t.hpp"
#include "proto/area_graph_diff.pb.h"
#include "proto/artifacts.pb.h"

namespace areagraph {

// Largest grid GridMapFromLcm accepts by default: ImportOptions.max_pixels's
// default, so a live map is limited like an imported one.
inline constexpr int64_t kMaxLcmGridCells = 100000000;

// Grid cell values of grid_map_t (ROS nav_msgs/OccupancyGrid): -1 unknown,
// else occupancy in percent. ROS map_saver's thresholds split 0..100.
inline constexpr int8_t kLcmUnknownCell = -1;
inline constexpr int8_t kLcmFreeCell = 0;
inline constexpr int8_t kLcmOccupiedCell = 100;
inline constexpr int8_t kLcmFreeMaxPercent = 25;
inline constexpr int8_t kLcmOccupiedMinPercent = 65;

// The Area Graph of `map_name` as sent on AREA_GRAPH; `cache_key` is its
// artifact's key. Ids are the stable ids (the graph's own for a graph
// without), version and predecessor_key come from graph.version();
// coordinates are the graph's metre fields. utime, sequence and map_utime are
// left 0 for the publisher to fill in.
areagraph_lcm::area_graph_t ToLcmAreaGraph(const std::string& map_name,
                                           const std::string& cache_key,
                                           const proto::AreaGraph& graph);

// `diff` (DiffAreaGraphs from the previous version to `after`, the graph with
// key `cache_key`) as sent on AREA_GRAPH_DIFF, with the added and changed
// areas and passages as they are in `after`. utime, sequence and map_utime
// are left 0. Throws InputError when the diff names ids `after` lacks.
areagraph_lcm::area_graph_diff_t ToLcmAreaGraphDiff(const std::string& map_name,
                                                    const std::string& cache_key,
                                                    const proto::AreaGraphDiff& diff,
                                                    const proto::AreaGraph& after);

// A received Area Graph as an AreaGraph artifact: ids become indices in
// message order and the message's (stable) ids the stable_id fields; version
// and predecessor_key go to `version` (left unset for version 0). Pixel
// polygons are recomputed from the metre ones through the frame; topology
// edge ids, which the LCM type does not carry, stay empty. Throws InputError
// when the message is inconsistent (bad frame or name, non-finite numbers,
// unknown kind, duplicate ids, passages joining unknown areas, a negative
// version).
proto::AreaGraph AreaGraphFromLcm(const areagraph_lcm::area_graph_t& message);

// `grid` as a grid_map_t (rows flipped to ROS order, cells to ROS values).
areagraph_lcm::grid_map_t ToLcmGridMap(const std::string& map_name, int64_t utime,
                                       const proto::GridMap& grid);

// A received grid as the GridMap that ag-import would make: cells classified
// with map_saver's thresholds and rows flipped so that row 0 is the top. Sets
// neither source_path nor source_digest. Throws InputError naming what is
// wrong: a bad name, a resolution that is not positive and finite, a
// non-finite origin, a size that is not positive or exceeds `max_cells`,
// num_cells or the cell count not matching width * height, or a cell value
// outside -1..100.
proto::GridMap GridMapFromLcm(const areagraph_lcm::grid_map_t& message,
                              int64_t max_cells = kMaxLcmGridCells);

// Decodes a grid_map_t from raw LCM bytes. The cell count is checked against
// the message size before decoding, so a forged count cannot make the decoder
// allocate gigabytes. Throws InputError for anything that is not a whole
// grid_map_t (wrong type fingerprint, truncated, trailing bytes).
areagraph_lcm::grid_map_t DecodeGridMapMessage(const void* data, int size);

// Decodes an area_graph_t from raw LCM bytes; throws InputError as above.
areagraph_lcm::area_graph_t DecodeAreaGraphMessage(const void* data, int size);

// Decodes an area_graph_diff_t from raw LCM bytes; throws InputError as above.
areagraph_lcm::area_graph_diff_t DecodeAreaGraphDiffMessage(const void* data, int size);

}  // namespace areagraph
