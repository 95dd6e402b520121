#pragma once

#include <string>

#include "proto/artifacts.pb.h"
#include "store/artifact_store.h"

namespace areagraph {

// A map's Area Graph from a store: the newest (as ag-export picks it: the
// ag-match head, unless ag-merge ran after it) when `version` is empty, else
// the version it names (a number, a key or key prefix, or "head"). Throws
// InputError when the map, its graph or the version is missing.
proto::AreaGraph ReadStoredAreaGraph(ArtifactStore& store, const std::string& map_name,
                                     const std::string& version = "");

}  // namespace areagraph
