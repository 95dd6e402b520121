#include "tests/support/raw_sqlite.h"

#include <sqlite3.h>

#include <memory>
#include <stdexcept>

namespace areagraph::testing {
namespace {

using Connection = std::unique_ptr<sqlite3, decltype(&sqlite3_close_v2)>;

Connection OpenRaw(const std::string& path) {
  sqlite3* db = nullptr;
  const int rc =
      sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr);
  Connection connection(db, &sqlite3_close_v2);
  if (rc != SQLITE_OK) throw std::runtime_error("raw open failed: " + path);
  sqlite3_busy_timeout(db, 10000);
  return connection;
}

void Check(sqlite3* db, int rc) {
  if (rc != SQLITE_OK && rc != SQLITE_ROW && rc != SQLITE_DONE) {
    throw std::runtime_error(std::string("raw sqlite: ") + sqlite3_errmsg(db));
  }
}

}  // namespace

void ExecSql(const std::string& path, const std::string& sql) {
  Connection db = OpenRaw(path);
  Check(db.get(), sqlite3_exec(db.get(), sql.c_str(), nullptr, nullptr, nullptr));
}

std::vector<std::string> QueryColumn(const std::string& path, const std::string& sql, int column) {
  Connection db = OpenRaw(path);
  sqlite3_stmt* raw = nullptr;
  Check(db.get(), sqlite3_prepare_v2(db.get(), sql.c_str(), -1, &raw, nullptr));
  std::unique_ptr<sqlite3_stmt, decltype(&sqlite3_finalize)> statement(raw, &sqlite3_finalize);
  std::vector<std::string> values;
  int rc = SQLITE_OK;
  while ((rc = sqlite3_step(raw)) == SQLITE_ROW) {
    const unsigned char* text = sqlite3_column_text(raw, column);
    values.emplace_back(text != nullptr ? reinterpret_cast<const char*>(text) : "");
  }
  Check(db.get(), rc);
  return values;
}

std::vector<std::string> HeadDigests(const std::string& path) {
  return QueryColumn(path,
                     "SELECT m.name || ' ' || h.stage || ' ' || a.payload_digest FROM heads h"
                     " JOIN maps m ON m.id = h.map_id JOIN artifacts a ON a.id = h.artifact_id"
                     " ORDER BY 1");
}

void FlipPayloadByte(const std::string& path, const std::string& cache_key, int offset) {
  const std::vector<std::string> ids =
      QueryColumn(path, "SELECT id FROM artifacts WHERE cache_key = '" + cache_key + "'");
  if (ids.size() != 1) throw std::runtime_error("no artifact " + cache_key);
  Connection db = OpenRaw(path);
  sqlite3_blob* blob = nullptr;
  Check(db.get(), sqlite3_blob_open(db.get(), "main", "artifacts", "payload", std::stoll(ids[0]),
                                    /*flags=*/1, &blob));
  char byte = 0;
  Check(db.get(), sqlite3_blob_read(blob, &byte, 1, offset));
  byte = static_cast<char>(byte ^ 0x5a);
  Check(db.get(), sqlite3_blob_write(blob, &byte, 1, offset));
  Check(db.get(), sqlite3_blob_close(blob));
}

NewArtifact MakeArtifact(const std::string& map_name, const std::string& stage,
                         const std::string& cache_key, const std::string& payload) {
  NewArtifact artifact;
  artifact.map_name = map_name;
  artifact.stage = stage;
  artifact.cache_key = cache_key;
  artifact.input_keys = {"input-" + cache_key + "-a", "input-" + cache_key + "-b"};
  artifact.options_text = "option: " + cache_key + "\nother: 2\n";
  artifact.stage_version = 3;
  artifact.proto_type = "areagraph.proto." + stage;
  artifact.payload = payload;
  artifact.elapsed_ms = 12.5;
  return artifact;
}

}  // namespace areagraph::testing
