#pragma once

#include "proto/artifacts.pb.h"
#include "proto/pipeline_options.pb.h"

namespace areagraph {

// The width W in metres that decides the room alpha radius (W / 2): the
// paper's strategy W = door + 0.1 m when the widest door is narrower than the
// narrowest corridor, else corridor - 0.1 m, when both widths are given
// (a width of 0 counts as not given, as in the stored canonical options);
// cut.room_width_m otherwise. Throws OptionsError for bad options
// (CheckCutOptions) and for a W wider than the whole map.
// Ignores cut.room_width_auto.
double RoomWidthM(const proto::CutOptions& options, const proto::MapFrame& frame);

// The W that ag-cut uses, and how it came about: RoomWidthM when door and
// corridor widths are given or cut.room_width_auto is off, else
// EstimateRoomWidth on the Topology Graph (falling back to
// cut.room_width_m when it finds neither doors nor corridors). Throws as
// RoomWidthM does.
proto::RoomWidthEstimate ChooseRoomWidth(const proto::CutOptions& options,
                                         const proto::MapFrame& frame,
                                         const proto::TopologyGraph& topology);

}  // namespace areagraph
