#pragma once

#include <google/protobuf/message.h>

#include "proto/artifacts.pb.h"
#include "tools/render/canvas.h"

namespace areagraph {

// One function per artifact: each draws what that stage found over the map.
void DrawCleanedMap(const proto::CleanedMap& cleaned, Canvas& canvas);
void DrawVoronoiDiagram(const proto::VoronoiDiagram& voronoi, Canvas& canvas);
void DrawTopologyGraph(const proto::TopologyGraph& graph, Canvas& canvas);
void DrawCutGraph(const proto::CutGraph& graph, Canvas& canvas);
void DrawAreaGraph(const proto::AreaGraph& graph, Canvas& canvas);
// Draws any artifact with the function of its type; a GridMap draws
// nothing (the map is the canvas).
void DrawArtifact(const google::protobuf::Message& artifact, Canvas& canvas);

// The doors (magenta rings, their width across) and corridors (cyan dots)
// that ag-cut found when it estimated W (cut.room_width_m=auto).
void DrawDetectedWidths(const proto::RoomWidthEstimate& estimate, double resolution_m,
                        Canvas& canvas);

}  // namespace areagraph
