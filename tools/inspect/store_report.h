#pragma once

#include <ostream>
#include <string>

#include "store/artifact_store.h"

namespace areagraph {

// One line per map: name, number of artifacts, source; then the maps that
// failed (recorded by runners), which may include maps without artifacts.
void PrintMapList(ArtifactStore& store, std::ostream& out);

// One line per artifact of a map: stage, short key, bytes, elapsed time,
// creation time, and whether it is the head of its stage; then the map's
// failure if one is recorded. A map with only a failure prints just that.
void PrintArtifactList(ArtifactStore& store, const std::string& map_name, std::ostream& out);

// Finds one artifact of a map by stage (its head) or by key prefix.
ArtifactRecord FindArtifact(ArtifactStore& store, const std::string& map_name,
                            const std::string& stage, const std::string& key_prefix);

// A few lines on what an artifact holds (frame, cell counts, graph sizes).
void PrintArtifactSummary(const ArtifactRecord& artifact, std::ostream& out);

// The artifact as JSON through protobuf's JSON printer.
void PrintArtifactJson(const ArtifactRecord& artifact, std::ostream& out);

}  // namespace areagraph
