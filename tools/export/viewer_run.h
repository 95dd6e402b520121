#pragma once

#include <string>
#include <vector>

#include "store/artifact_store.h"
#include "tools/export/viewer_page.pb.h"

namespace areagraph {

// The artifacts of one pipeline run of a map, in pipeline order: the one
// whose key starts with `key_prefix` (by default the head of the latest
// stage the map has, normally merge) and those reached from it through input
// keys. Walking the keys rather than reading every stage's head keeps the
// run consistent when a head was moved by a later run of one stage. Throws
// InputError when the map or key is unknown.
std::vector<ArtifactRecord> RunArtifacts(ArtifactStore& store, const std::string& map_name,
                                         const std::string& key_prefix);

// The viewer's layers and records for those artifacts. With `first` (the
// diff view's other run), stages whose artifact `first` already holds are
// marked same_as_first and their layers left out.
viewer::Run ViewerRunOf(const std::vector<ArtifactRecord>& artifacts, const std::string& label,
                        const viewer::Run* first = nullptr);

}  // namespace areagraph
