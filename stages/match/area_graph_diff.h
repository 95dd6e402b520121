#pragma once

#include <string>

#include "proto/area_graph_diff.pb.h"
#include "proto/artifacts.pb.h"

namespace areagraph {

// What counts as a change in a diff.
struct DiffThresholds {
  // An area grew or shrank when its cells changed by more than this fraction
  // of what it had; a passage changed when its width did.
  double size = 0.1;
  // A passage changed when its point moved more than this (metres).
  double passage_m = 0.5;
};

// What changed from `before` to `after`, two versions of one map's Area Graph
// (match artifacts), by stable id. Areas are compared by their cells on
// `after`'s grid (RasterizeAreas): an added area came from the removed or
// kept area that held most of its cells, if at least half of them (else it is
// new space), and a removed area went into the area that took most of its
// cells, if at least half. A kept area that lost cells to added areas split,
// one that took removed areas merged. Throws InputError when either graph has
// no stable ids.
proto::AreaGraphDiff DiffAreaGraphs(const proto::AreaGraph& before, const proto::AreaGraph& after,
                                    const DiffThresholds& thresholds = {});

// The diff as text, one line per area or passage that changed and a count of
// the rest.
std::string FormatAreaGraphDiff(const proto::AreaGraphDiff& diff);

}  // namespace areagraph
