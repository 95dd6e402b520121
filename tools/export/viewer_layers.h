#pragma once

#include <string>

#include "proto/artifacts.pb.h"
#include "proto/pipeline_options.pb.h"
#include "tools/export/viewer_page.pb.h"

namespace areagraph {

// One function per artifact: each turns what a stage found into the
// viewer's layer for it (see viewer_page.proto), in map pixels.

// The grid as an 8-bit grey PNG: free white, occupied black, unknown grey.
std::string GridMapPng(const proto::GridMap& grid);

// What cleaning changed. `grid` (the cleaned map's input) may be null, and
// then freed unknown cells are not marked.
viewer::CleanLayer CleanLayerOf(const proto::CleanedMap& cleaned, const proto::GridMap* grid);

// The Voronoi edges (rays left out) chained into one path per clearance band.
viewer::VoronoiLayer VoronoiLayerOf(const proto::VoronoiDiagram& voronoi);

viewer::TopologyLayer TopologyLayerOf(const proto::TopologyGraph& graph);

viewer::CutLayer CutLayerOf(const proto::CutGraph& graph);

// W with the doors and corridors behind it and the rule that chose it.
viewer::RoomWidth RoomWidthOf(const proto::RoomWidthEstimate& estimate,
                              const proto::CutOptions& options);

viewer::AreaLayer AreaLayerOf(const proto::AreaGraph& graph);

}  // namespace areagraph
