#pragma once

#include <vector>

#include "proto/artifacts.pb.h"

namespace areagraph {

// `base` (frame, header, version) with these areas and passages: areas and
// passages numbered in order, each area's passage_ids and the component
// count worked out again. The passages' area_a and area_b are indices into
// `areas`. What ag-match's folds and splits end with.
proto::AreaGraph AssembleGraph(const proto::AreaGraph& base, std::vector<proto::Area> areas,
                               std::vector<proto::Passage> passages);

}  // namespace areagraph
