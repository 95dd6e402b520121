#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace areagraph {

// The columns of an artifact row that its payload digest does not cover and
// that tools act on: which map and stage it belongs to, its key (what heads,
// inputs and cache lookups name), its input keys, options, stage version,
// type, payload digest, summary line and creation time (merge orders heads
// by it). A bit flip in any of them changes the row's digest (schema 6).
struct ArtifactRowFields {
  std::string_view map_name;
  std::string_view stage;
  std::string_view cache_key;
  std::string_view input_keys;  // newline-joined, as stored
  std::string_view options_text;
  int64_t stage_version = 0;
  std::string_view proto_type;
  std::string_view payload_digest;
  std::string_view summary_line;
  std::string_view created_at;
};

// Lower-case hex SHA-256 over the fields, each length-prefixed.
std::string ArtifactRowDigest(const ArtifactRowFields& fields);

// UTC now as the store writes times: ISO 8601 with milliseconds
// ("2026-12-07T10:11:12.345Z"), the format of SQLite's strftime('%Y-%m-%dT%H:%M:%fZ').
std::string StoreTimeNow();

}  // namespace areagraph
