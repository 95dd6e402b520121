#pragma once

#include <string>
#include <vector>

namespace areagraph {

// The cache key of a stage run: SHA-256 over the stage name, its version, the
// canonical serialized options and the digests of its inputs, each
// length-prefixed so that no two different tuples collide by concatenation.
std::string ComputeCacheKey(const std::string& stage, int stage_version,
                            const std::string& canonical_options,
                            const std::vector<std::string>& input_digests);

}  // namespace areagraph
