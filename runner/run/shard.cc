#include "runner/run/shard.h"

#include <cstdint>
#include <regex>

#include "common/error.h"
#include "store/digest.h"

namespace areagraph {

Shard ParseShard(const std::string& text) {
  static const std::regex kPattern("([0-9]{1,6})/([0-9]{1,6})");
  std::smatch match;
  if (!std::regex_match(text, match, kPattern)) {
    throw OptionsError("--shard '" + text + "' is not K/N (for example 0/4)");
  }
  Shard shard{std::stoi(match[1]), std::stoi(match[2])};
  if (shard.count < 1 || shard.index >= shard.count) {
    throw OptionsError("--shard " + text + ": K must be between 0 and N-1 (" +
                       (shard.count < 1 ? std::string("N must be at least 1")
                                        : "0.." + std::to_string(shard.count - 1)) +
                       ")");
  }
  return shard;
}

bool InShard(const std::string& map_name, const Shard& shard) {
  const std::string digest = Sha256Hex(map_name);
  const uint64_t hash = std::stoull(digest.substr(0, 15), nullptr, 16);
  return static_cast<int>(hash % static_cast<uint64_t>(shard.count)) == shard.index;
}

}  // namespace areagraph
