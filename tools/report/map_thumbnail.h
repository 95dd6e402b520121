#pragma once

#include <string>
#include <vector>

#include "store/artifact_store.h"

namespace areagraph {

// A PNG of at most `max_side` pixels a side for the collection index: the
// areas of the run's Area Graph over its cleaned map (or the grid, or just
// the map when the run stopped earlier), drawn as ag-render draws them.
// Empty when the run has no map artifact.
std::string MapThumbnailPng(const std::vector<ArtifactRecord>& run, int max_side);

}  // namespace areagraph
