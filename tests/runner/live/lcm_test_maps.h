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

// Success when `body` throws an areagraph::Error whose message contains
// `expected`.
::testing::AssertionResult ThrowsMessage(const std::function<void()>& body,
                                         const std::string& expected);

}  // namespace areagraph::testing
