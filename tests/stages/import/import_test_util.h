#pragma once

#include <memory>
#include <string>

#include "proto/artifacts.pb.h"
#include "store/artifact_store.h"

namespace areagraph::testing {

// Writes the two-room example plan (240x140 px), optionally with the door
// closed, to `path` as PNG.
void WriteTwoRoomPng(const std::string& path, bool door_open = true);

// The head GridMap of `map_name` in the store at `store_path`.
proto::GridMap ReadHeadGridMap(const std::string& store_path, const std::string& map_name,
                               std::string* cache_key = nullptr);

// Number of artifacts the store holds for `map_name`.
size_t ArtifactCount(const std::string& store_path, const std::string& map_name);

// `sqlite3 DB .dump`: the store's whole content as SQL text.
std::string DumpStore(const std::string& store_path);

}  // namespace areagraph::testing
