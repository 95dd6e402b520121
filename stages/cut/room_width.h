#pragma once

#include "proto/artifacts.pb.h"
#include "proto/pipeline_options.pb.h"

namespace areagraph {

// The width W in metres that decides the room alpha radius (W / 2): the
// paper's strategy W = door + 0.1 m when the widest door is narrower than the
// narrowest corridor, else corridor - 0.1 m, when both widths are given
// (a width of 0 counts as not given, as in the stored canonical options);
// cut.room_width_m otherwise. Throws OptionsError for a non-positive or
// non-finite result, for one width without the other, and for a W wider
// than the whole map.
double RoomWidthM(const proto::CutOptions& options, const proto::MapFrame& frame);

}  // namespace areagraph
