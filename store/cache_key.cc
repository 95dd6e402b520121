#include "store/cache_key.h"

#include "store/digest.h"

namespace areagraph {
namespace {

void AddField(Sha256& sha, const std::string& field) {
  sha.Update(std::to_string(field.size()));
  sha.Update(":");
  sha.Update(field);
}

}  // namespace

std::string ComputeCacheKey(const std::string& stage, int stage_version,
                            const std::string& canonical_options,
                            const std::vector<std::string>& input_digests) {
  Sha256 sha;
  AddField(sha, "areagraph-cache-key-v1");
  AddField(sha, stage);
  AddField(sha, std::to_string(stage_version));
  AddField(sha, canonical_options);
  AddField(sha, std::to_string(input_digests.size()));
  for (const std::string& digest : input_digests) AddField(sha, digest);
  return sha.FinishHex();
}

}  // namespace areagraph
