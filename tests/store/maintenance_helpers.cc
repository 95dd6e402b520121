#include "tests/store/maintenance_helpers.h"

#include <algorithm>
#include <stdexcept>

#include "store/digest.h"
#include "tests/support/raw_sqlite.h"

namespace areagraph::testing {

std::string ProtoBytes(const std::string& text) {
  if (text.size() > 127) throw std::invalid_argument("ProtoBytes: text too long");
  return std::string("\x0a", 1) + static_cast<char>(text.size()) + text;
}

NewArtifact Artifact(const std::string& map_name, const std::string& stage, const std::string& key,
                     const std::vector<std::string>& input_keys, const std::string& text) {
  NewArtifact artifact;
  artifact.map_name = map_name;
  artifact.stage = stage;
  artifact.cache_key = key;
  artifact.input_keys = input_keys;
  artifact.options_text = "";
  artifact.stage_version = 1;
  artifact.proto_type = "areagraph.proto.Test";
  artifact.payload = ProtoBytes(text);
  artifact.elapsed_ms = 1;
  return artifact;
}

void SetCreatedAt(const std::string& path, const std::string& key, const std::string& time) {
  ExecSqlAndReseal(
      path, "UPDATE artifacts SET created_at = '" + time + "' WHERE cache_key = '" + key + "'");
}

void SetFailedAt(const std::string& path, const std::string& map_name, const std::string& time) {
  ExecSql(path,
          "UPDATE failures SET failed_at = '" + time + "' WHERE map_name = '" + map_name + "'");
}

void CreateVersion1Store(const std::string& path) {
  const std::string import_payload = ProtoBytes("v1 grid"), clean_payload = ProtoBytes("v1 clean");
  const auto blob = [](const std::string& bytes) {
    std::string hex = "X'";
    for (unsigned char c : bytes) {
      const char* digits = "0123456789abcdef";
      hex += digits[c >> 4];
      hex += digits[c & 15];
    }
    return hex + "'";
  };
  ExecSql(path,
          R"sql(
CREATE TABLE maps (
  id INTEGER PRIMARY KEY,
  name TEXT NOT NULL UNIQUE,
  source_path TEXT NOT NULL DEFAULT '',
  source_digest TEXT NOT NULL DEFAULT '');
CREATE TABLE artifacts (
  id INTEGER PRIMARY KEY,
  map_id INTEGER NOT NULL REFERENCES maps(id) ON DELETE CASCADE,
  stage TEXT NOT NULL,
  cache_key TEXT NOT NULL,
  input_keys TEXT NOT NULL,
  options TEXT NOT NULL,
  stage_version INTEGER NOT NULL,
  proto_type TEXT NOT NULL,
  payload BLOB NOT NULL,
  payload_digest TEXT NOT NULL,
  created_at TEXT NOT NULL,
  elapsed_ms REAL NOT NULL,
  UNIQUE (map_id, cache_key));
CREATE INDEX artifacts_by_map_and_time ON artifacts (map_id, created_at);
CREATE TABLE heads (
  map_id INTEGER NOT NULL REFERENCES maps(id) ON DELETE CASCADE,
  stage TEXT NOT NULL,
  artifact_id INTEGER NOT NULL REFERENCES artifacts(id) ON DELETE CASCADE,
  PRIMARY KEY (map_id, stage));
CREATE INDEX heads_by_artifact ON heads (artifact_id);
PRAGMA journal_mode = WAL;
INSERT INTO maps VALUES (1, 'old_map', 'old.png', 'file-digest');
)sql" +
              std::string(
                  "INSERT INTO artifacts VALUES (1, 1, 'import', 'v1-import', 'file-digest', '', "
                  "1, 'areagraph.proto.GridMap', ") +
              blob(import_payload) + ", '" + Sha256Hex(import_payload) +
              "', '2025-01-01T00:00:00.000Z', 5);"
              "INSERT INTO artifacts VALUES (2, 1, 'clean', 'v1-clean', 'v1-import', '', 3, "
              "'areagraph.proto.CleanedMap', " +
              blob(clean_payload) + ", '" + Sha256Hex(clean_payload) +
              "', '2025-01-01T00:00:01.000Z', 7);"
              "INSERT INTO heads VALUES (1, 'import', 1), (1, 'clean', 2);"
              "PRAGMA user_version = 1;");
}

std::vector<std::string> KeysOf(ArtifactStore& store, const std::string& map_name) {
  std::vector<std::string> keys;
  for (const ArtifactRecord& artifact : store.ReadArtifactSummaries(map_name)) {
    keys.push_back(artifact.cache_key);
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

std::vector<std::string> MapNames(ArtifactStore& store) {
  std::vector<std::string> names;
  for (const MapRecord& map : store.ReadAllMaps()) names.push_back(map.name);
  return names;
}

}  // namespace areagraph::testing
