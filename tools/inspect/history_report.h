#pragma once

#include <ostream>
#include <string>

#include "stages/match/area_graph_diff.h"
#include "store/artifact_store.h"

namespace areagraph {

// One line per version of a map's Area Graph, oldest first: number, key,
// time, predecessor, what the graph holds, and whether it is the head or no
// longer stored (gc drops superseded versions that no head reaches). Throws
// InputError when the map has no history.
void PrintHistory(ArtifactStore& store, const std::string& map_name, std::ostream& out);

// The key of a version of a map given as its number ("3"), a key or a unique
// key prefix, or "head". Throws InputError naming what is wrong.
std::string FindVersionKey(ArtifactStore& store, const std::string& map_name,
                           const std::string& version);

// What changed from version `from` to `to` of a map (FindVersionKey forms),
// as text or as JSON (the AreaGraphDiff message).
void PrintVersionDiff(ArtifactStore& store, const std::string& map_name, const std::string& from,
                      const std::string& to, const DiffThresholds& thresholds, bool json,
                      std::ostream& out);

}  // namespace areagraph
