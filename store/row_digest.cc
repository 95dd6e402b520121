#include "store/row_digest.h"

#include <chrono>
#include <cstdio>
#include <ctime>

#include "store/digest.h"

namespace areagraph {
namespace {

void AddField(Sha256& sha, std::string_view field) {
  sha.Update(std::to_string(field.size()));
  sha.Update(":");
  sha.Update(field);
}

}  // namespace

std::string ArtifactRowDigest(const ArtifactRowFields& fields) {
  Sha256 sha;
  AddField(sha, "areagraph-artifact-row-v1");
  AddField(sha, fields.map_name);
  AddField(sha, fields.stage);
  AddField(sha, fields.cache_key);
  AddField(sha, fields.input_keys);
  AddField(sha, fields.options_text);
  AddField(sha, std::to_string(fields.stage_version));
  AddField(sha, fields.proto_type);
  AddField(sha, fields.payload_digest);
  AddField(sha, fields.summary_line);
  AddField(sha, fields.created_at);
  return sha.FinishHex();
}

std::string StoreTimeNow() {
  const auto now = std::chrono::system_clock::now();
  const std::time_t seconds = std::chrono::system_clock::to_time_t(now);
  const auto millis =
      std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  char text[80];  // room for any int the fields may hold, so the compiler sees no truncation
  std::snprintf(text, sizeof(text), "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", utc.tm_year + 1900,
                utc.tm_mon + 1, utc.tm_mday, utc.tm_hour, utc.tm_min, utc.tm_sec,
                static_cast<int>(millis));
  return text;
}

}  // namespace areagraph
