#pragma once

#include <vector>

#include "proto/artifacts.pb.h"
#include "proto/pipeline_options.pb.h"
#include "stages/cut/closed_passages.h"
#include "stages/cut/openings.h"

namespace areagraph {

// The paper's W (metres): the room width where cut.room_width_m is 0 and the
// map shows neither a door nor a corridor to estimate it from.
inline constexpr double kPaperRoomWidthM = 1.25;

// Whether W is estimated from the map: cut.room_width_m is 0 (`auto`).
inline bool EstimatesRoomWidth(const proto::CutOptions& options) {
  return options.room_width_m() == 0;
}

// The width W in metres that decides the room alpha radius (W / 2): the
// paper's strategy W = door + 0.1 m when the widest door is narrower than the
// narrowest corridor, else corridor - 0.1 m, when both widths are given
// (a width of 0 counts as not given, as in the stored canonical options);
// cut.room_width_m otherwise, and kPaperRoomWidthM where that is 0 (to be
// estimated). Throws OptionsError for bad options (CheckCutOptions) and for
// a W wider than the whole map.
double RoomWidthM(const proto::CutOptions& options, const proto::MapFrame& frame);

// The W that ag-cut uses, and how it came about: RoomWidthM when door and
// corridor widths are given or cut.room_width_m is a number, else
// EstimateRoomWidth on the connected part of the Topology Graph with the
// most edge length (falling back to kPaperRoomWidthM when it finds neither
// doors nor corridors; never below MinRoomWidthM(robot_width_m), with
// `robot_width_m` clean.robot_width_m). Throws as RoomWidthM does.
proto::RoomWidthEstimate ChooseRoomWidth(const proto::CutOptions& options,
                                         const proto::MapFrame& frame,
                                         const proto::TopologyGraph& topology,
                                         double robot_width_m);

// Local door decisions (cut.room_width_open_doors): an automatic W need
// only stop the doors that no opening closes. The estimate's doors are the
// narrowing openings (widest first); a door that a rule closed, or that
// lies on a `closed` line (a wall gap's), keeps the disk out whatever W is.
// W becomes the rule's width from the doors left open (WidestDoorM of
// them, or none), kept above the narrowest corridor (corridors stay
// room-less) and never above the estimate's W; the widest open door is
// recorded. A building whose double doors all have wall jambs then gets W
// from its single doors. `robot_width_m` as for ChooseRoomWidth.
void KeepWidthAboveOpenDoors(const std::vector<Opening>& openings, const ClosedLines& closed,
                             const proto::CutOptions& options, double robot_width_m,
                             proto::RoomWidthEstimate* estimate);

}  // namespace areagraph
