#pragma once

#include <string>

namespace areagraph {

// A share of a collection: the maps whose name hashes to `index` modulo `count`.
struct Shard {
  int index = 0;
  int count = 1;
};

// Parses "K/N" with 0 <= K < N. Throws OptionsError otherwise.
Shard ParseShard(const std::string& text);

// Whether `map_name` belongs to `shard`. Stable across runs, machines and
// collection order: it depends on the name's SHA-256 only.
bool InShard(const std::string& map_name, const Shard& shard);

}  // namespace areagraph
