#include "tests/support/raw_sqlite.h"

#include <sqlite3.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <memory>
#include <stdexcept>

#include "store/payload_codec.h"
#include "store/sqlite_artifact_store.h"
#include "store/sqlite_store_sql.h"

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

void ExecSqlAndReseal(const std::string& path, const std::string& sql) {
  Connection db = OpenRaw(path);
  store_internal::RegisterRowDigestFunction(db.get(), path);
  Check(db.get(), sqlite3_exec(db.get(), sql.c_str(), nullptr, nullptr, nullptr));
  Check(db.get(), sqlite3_exec(db.get(), store_sql::kFillRowDigests, nullptr, nullptr, nullptr));
}

struct WriteLockHolder::Connection {
  Connection(sqlite3* db) : db(db, &sqlite3_close_v2) {}  // NOLINT
  std::unique_ptr<sqlite3, decltype(&sqlite3_close_v2)> db;
};

WriteLockHolder::WriteLockHolder(const std::string& path)
    : connection_(std::make_unique<Connection>(OpenRaw(path).release())) {
  sqlite3* db = connection_->db.get();
  Check(db, sqlite3_exec(db, "BEGIN IMMEDIATE", nullptr, nullptr, nullptr));
}

WriteLockHolder::~WriteLockHolder() { Release(); }

void WriteLockHolder::Release() {
  if (!connection_) return;
  sqlite3_exec(connection_->db.get(), "COMMIT", nullptr, nullptr, nullptr);
  connection_.reset();
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

std::vector<std::string> StoreHeadDigests(const std::string& path) {
  const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(path, StoreMode::kReadOnly);
  std::vector<std::string> heads;
  for (const MapRecord& map : store->ReadAllMaps()) {
    for (const ArtifactRecord& artifact : store->ReadArtifactSummaries(map.name)) {
      if (artifact.is_head) {
        heads.push_back(map.name + " " + artifact.stage + " " + artifact.payload_digest);
      }
    }
  }
  std::sort(heads.begin(), heads.end());
  return heads;
}

void RewriteAsSchema4(const std::string& path) {
  const std::vector<std::string> ids = QueryColumn(path, "SELECT id FROM artifacts");
  Connection db = OpenRaw(path);
  for (const std::string& id : ids) {
    sqlite3_stmt* raw = nullptr;
    Check(db.get(),
          sqlite3_prepare_v2(db.get(), "SELECT payload, payload_codec FROM artifacts WHERE id = ?1",
                             -1, &raw, nullptr));
    std::unique_ptr<sqlite3_stmt, decltype(&sqlite3_finalize)> read(raw, &sqlite3_finalize);
    sqlite3_bind_int64(raw, 1, std::stoll(id));
    Check(db.get(), sqlite3_step(raw));
    const char* bytes = static_cast<const char*>(sqlite3_column_blob(raw, 0));
    const std::string payload =
        DecodePayload(std::string_view(bytes != nullptr ? bytes : "", sqlite3_column_bytes(raw, 0)),
                      sqlite3_column_int64(raw, 1));
    read.reset();
    Check(db.get(), sqlite3_prepare_v2(db.get(), "UPDATE artifacts SET payload = ?1 WHERE id = ?2",
                                       -1, &raw, nullptr));
    std::unique_ptr<sqlite3_stmt, decltype(&sqlite3_finalize)> write(raw, &sqlite3_finalize);
    sqlite3_bind_blob(raw, 1, payload.data(), static_cast<int>(payload.size()), SQLITE_TRANSIENT);
    sqlite3_bind_int64(raw, 2, std::stoll(id));
    Check(db.get(), sqlite3_step(raw));
  }
  Check(db.get(), sqlite3_exec(db.get(),
                               "ALTER TABLE artifacts DROP COLUMN row_digest;"
                               "ALTER TABLE artifacts DROP COLUMN payload_codec;"
                               "ALTER TABLE artifacts DROP COLUMN payload_size;"
                               "PRAGMA user_version = 4;",
                               nullptr, nullptr, nullptr));
}

void RewriteAsSchema5(const std::string& path) {
  ExecSql(path,
          "ALTER TABLE artifacts DROP COLUMN row_digest;"
          "PRAGMA user_version = 5;");
}

void ReplaceOnceInFile(const std::string& path, const std::string& from, const std::string& to) {
  if (from.size() != to.size()) throw std::runtime_error("replacement of another length");
  ExecSql(path, "PRAGMA wal_checkpoint(TRUNCATE)");
  std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const size_t at = bytes.find(from);
  if (at == std::string::npos || bytes.find(from, at + 1) != std::string::npos) {
    throw std::runtime_error("'" + from + "' is not in " + path + " exactly once");
  }
  file.clear();
  file.seekp(static_cast<std::streamoff>(at));
  file.write(to.data(), static_cast<std::streamsize>(to.size()));
  if (!file.flush()) throw std::runtime_error("cannot change " + path);
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
  offset %= std::max(1, sqlite3_blob_bytes(blob));  // payloads are stored compressed
  Check(db.get(), sqlite3_blob_read(blob, &byte, 1, offset));
  byte = static_cast<char>(byte ^ 0x5a);
  Check(db.get(), sqlite3_blob_write(blob, &byte, 1, offset));
  Check(db.get(), sqlite3_blob_close(blob));
}

void DamageRootPage(const std::string& path, const std::string& object_name, int bytes) {
  ExecSql(path, "PRAGMA wal_checkpoint(TRUNCATE)");
  const std::vector<std::string> root =
      QueryColumn(path, "SELECT rootpage FROM sqlite_master WHERE name = '" + object_name + "'");
  const std::vector<std::string> page_size = QueryColumn(path, "PRAGMA page_size");
  if (root.size() != 1 || page_size.size() != 1) throw std::runtime_error("no " + object_name);
  std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
  const std::streamoff offset = (std::stoll(root[0]) - 1) * std::stoll(page_size[0]);
  std::string page(static_cast<size_t>(bytes), '\0');
  file.seekg(offset);
  file.read(page.data(), bytes);
  for (char& byte : page) byte = static_cast<char>(~byte);
  file.seekp(offset);
  file.write(page.data(), bytes);
  if (!file.flush()) throw std::runtime_error("cannot damage " + path);
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
