#pragma once

#include <optional>
#include <string>

#include "proto/artifacts.pb.h"
#include "proto/pipeline_options.pb.h"
#include "stages/common/stage_info.h"
#include "stages/import/map_yaml.h"

namespace areagraph {

// The files of one map, read once: the bytes that are decoded are exactly the
// bytes that are digested.
struct ImportSource {
  // The path as the user gave it: an image or a map_server YAML.
  std::string given_path;
  std::string image_path;
  std::string image_bytes;
  // Set when a YAML was given, or found beside the image as <stem>.yaml.
  std::optional<std::string> yaml_path;
  std::string yaml_bytes;
  std::optional<MapYaml> yaml;

  // SHA-256 (hex) of the image bytes followed by the YAML bytes: the input
  // digest of the import's cache key and GridMap.source_digest. Computed
  // once (the bytes are not changed after reading) and kept.
  std::string Digest() const;
  bool HasDigest() const { return !digest_memo.empty(); }

  // Digest()'s answer, once computed.
  mutable std::string digest_memo;
};

// Reads a map given as an image (using <stem>.yaml beside it when present)
// or as a map_server YAML ending in .yaml or .yml (whose `image` is then
// read). Throws InputError for missing or unreadable files and bad YAML.
ImportSource ReadImportSource(const std::string& path);

// The map name used when none is given: the file name without extension.
std::string DefaultMapName(const std::string& path);

// Decodes and classifies the image. With a YAML, its resolution, origin and
// thresholds apply; without, options.resolution_m, a zero origin and the
// grey thresholds of GreyThresholdRule. Throws InputError or OptionsError.
// The source's digest, unless already known, is computed beside the decode
// (on OpenCV's pool).
proto::GridMap ImportGridMap(const ImportSource& source, const proto::ImportOptions& options);

// What enters the import's cache key and map row for `source`.
StageInputs ImportInputs(const ImportSource& source);

// The cache key of importing `source` with `options`, known without decoding.
std::string ImportCacheKey(const ImportSource& source, const proto::ImportOptions& options);

}  // namespace areagraph
