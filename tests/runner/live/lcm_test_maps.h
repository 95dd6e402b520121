#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "proto/artifacts.pb.h"

namespace areagraph::testing {

// A 3 x 2 grid at 0.05 m with a rotated origin; top row free, occupied,
// unknown, bottom row the reverse.
proto::GridMap MakeGridMap();

// Two areas (a room with a hole, id 0, and a corridor, id 1) joined by
// passage 7, in a 100 x 80 px frame at 0.05 m.
proto::AreaGraph MakeAreaGraph();

// Two versions of MakeAreaGraph's map as ag-match makes them (stable ids,
// version 1 and 2, predecessor "first-key"): in the second the corridor is
// 30 % larger, a dead end (stable id 2) opens off it through passage 1, and
// the door (stable id 0) moved 0.1 m.
void MakeTwoVersions(proto::AreaGraph& first, proto::AreaGraph& second);

// Success when `body` throws an areagraph::Error whose message contains
// `expected`.
::testing::AssertionResult ThrowsMessage(const std::function<void()>& body,
                                         const std::string& expected);

}  // namespace areagraph::testing
