#pragma once

#include <string>
#include <vector>

#include "store/artifact_store.h"

// Building blocks for the store maintenance tests: artifacts with chosen
// input keys, controlled timestamps, and a store as version 1 wrote it.
namespace areagraph::testing {

// `text` as protobuf wire bytes (field 1, a string), so Verify accepts it.
std::string ProtoBytes(const std::string& text);

// An artifact of (map, stage) with key `key` and the given input keys.
NewArtifact Artifact(const std::string& map_name, const std::string& stage, const std::string& key,
                     const std::vector<std::string>& input_keys,
                     const std::string& text = "payload");

// Timestamps set by hand, to order artifacts and failures in tests.
void SetCreatedAt(const std::string& path, const std::string& key, const std::string& time);
void SetFailedAt(const std::string& path, const std::string& map_name, const std::string& time);

// A store in schema version 1, as version-1 builds wrote it (schema frozen
// here): map "old_map" from "old.png" with an import (key "v1-import") and a
// clean (key "v1-clean") artifact, both heads.
void CreateVersion1Store(const std::string& path);

// The cache keys of a map's artifacts, sorted.
std::vector<std::string> KeysOf(ArtifactStore& store, const std::string& map_name);

// The names of the store's maps, sorted.
std::vector<std::string> MapNames(ArtifactStore& store);

}  // namespace areagraph::testing
