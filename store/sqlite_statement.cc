#include "store/sqlite_statement.h"

#include <cctype>
#include <cstring>
#include <utility>

#include "common/error.h"

namespace areagraph {
namespace {

const char* TypeName(int type);

}  // namespace

std::string SqliteReason(sqlite3* db, int rc) {
  // For a failed system call (a -shm that cannot be made on a full disk is
  // "disk I/O error" to SQLite) the system's own reason says what to fix.
  const int code = rc & 0xff;
  if (db != nullptr && (code == SQLITE_IOERR || code == SQLITE_FULL || code == SQLITE_CANTOPEN) &&
      sqlite3_system_errno(db) != 0) {
    std::string text = std::strerror(sqlite3_system_errno(db));
    if (!text.empty())
      text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
    return text;
  }
  // SQLite keeps no errno for a write that found the disk full.
  if (code == SQLITE_FULL) return "no space left on device";
  if (db != nullptr && (sqlite3_errcode(db) & 0xff) == code) return sqlite3_errmsg(db);
  return sqlite3_errstr(rc);
}

namespace {

const char* TypeName(int type) {
  switch (type) {
    case SQLITE_INTEGER:
      return "INTEGER";
    case SQLITE_FLOAT:
      return "REAL";
    case SQLITE_TEXT:
      return "TEXT";
    case SQLITE_BLOB:
      return "BLOB";
    default:
      return "NULL";
  }
}

}  // namespace

void CheckSqlite(sqlite3* db, const std::string& store_path, int rc, const std::string& action) {
  if (rc == SQLITE_OK || rc == SQLITE_ROW || rc == SQLITE_DONE) return;
  const std::string reason = SqliteReason(db, rc);
  switch (rc & 0xff) {
    case SQLITE_BUSY:
    case SQLITE_LOCKED:
      throw StoreError("store '" + store_path +
                       "' is locked by another process (gave up after waiting up to " +
                       std::to_string(kStoreBusyTimeoutMs / 1000) + " s) while " + action);
    case SQLITE_READONLY:
      throw StoreError("store '" + store_path + "' is read-only (" + reason + ") while " + action);
    case SQLITE_CORRUPT:
    case SQLITE_NOTADB:
      throw StoreError("store '" + store_path + "' is damaged (" + reason + ") while " + action);
    default:
      throw StoreError("store '" + store_path + "': " + reason + " while " + action);
  }
}

SqliteStatement& LazyStatement::operator*() const {
  if (!statement_) statement_ = std::make_unique<SqliteStatement>(db_, *store_path_, sql_, action_);
  return *statement_;
}

SqliteStatement::SqliteStatement(sqlite3* db, const std::string& store_path, const char* sql,
                                 std::string action)
    : db_(db), store_path_(store_path), action_(std::move(action)) {
  CheckSqlite(db_, store_path_,
              sqlite3_prepare_v3(db_, sql, -1, SQLITE_PREPARE_PERSISTENT, &stmt_, nullptr),
              "preparing the statement for " + action_);
}

SqliteStatement::~SqliteStatement() { sqlite3_finalize(stmt_); }

void SqliteStatement::Check(int rc) const { CheckSqlite(db_, store_path_, rc, action_); }

void SqliteStatement::BindText(int index, std::string_view text) {
  Check(sqlite3_bind_text64(stmt_, index, text.data(), text.size(), SQLITE_TRANSIENT, SQLITE_UTF8));
}

void SqliteStatement::BindBlob(int index, std::string_view bytes) {
  BindBlobWith(index, bytes, SQLITE_TRANSIENT);
}

void SqliteStatement::BindBlobUncopied(int index, std::string_view bytes) {
  BindBlobWith(index, bytes, SQLITE_STATIC);
}

void SqliteStatement::BindBlobWith(int index, std::string_view bytes, void (*lifetime)(void*)) {
  // A null pointer would bind NULL; an empty payload must stay a zero-length BLOB.
  static const char kEmpty = 0;
  const char* data = bytes.empty() ? &kEmpty : bytes.data();
  Check(sqlite3_bind_blob64(stmt_, index, data, bytes.size(), lifetime));
}

void SqliteStatement::BindInt64(int index, int64_t value) {
  Check(sqlite3_bind_int64(stmt_, index, value));
}

void SqliteStatement::BindDouble(int index, double value) {
  Check(sqlite3_bind_double(stmt_, index, value));
}

bool SqliteStatement::Step() {
  const int rc = sqlite3_step(stmt_);
  Check(rc);
  return rc == SQLITE_ROW;
}

void SqliteStatement::CheckColumnType(int index, const char* column, int expected,
                                      const char* expected_name, int also_allowed) const {
  const int type = sqlite3_column_type(stmt_, index);
  if (type == expected || type == also_allowed) return;
  throw StoreError("store '" + store_path_ + "' is damaged: column " + column + " holds " +
                   TypeName(type) + " where " + expected_name +
                   " belongs (edited by hand?) while " + action_);
}

std::string SqliteStatement::ColumnText(int index, const char* column) const {
  CheckColumnType(index, column, SQLITE_TEXT, "TEXT");
  const unsigned char* text = sqlite3_column_text(stmt_, index);
  const int size = sqlite3_column_bytes(stmt_, index);
  if (text == nullptr) return std::string();
  return std::string(reinterpret_cast<const char*>(text), static_cast<size_t>(size));
}

std::string SqliteStatement::ColumnBlob(int index, const char* column) const {
  return std::string(ColumnBlobView(index, column));
}

std::string_view SqliteStatement::ColumnBlobView(int index, const char* column) const {
  CheckColumnType(index, column, SQLITE_BLOB, "BLOB");
  const void* data = sqlite3_column_blob(stmt_, index);
  const int size = sqlite3_column_bytes(stmt_, index);
  if (data == nullptr || size == 0) return std::string_view();
  return std::string_view(static_cast<const char*>(data), static_cast<size_t>(size));
}

int64_t SqliteStatement::ColumnInt64(int index, const char* column) const {
  CheckColumnType(index, column, SQLITE_INTEGER, "INTEGER");
  return sqlite3_column_int64(stmt_, index);
}

double SqliteStatement::ColumnDouble(int index, const char* column) const {
  CheckColumnType(index, column, SQLITE_FLOAT, "REAL", SQLITE_INTEGER);
  return sqlite3_column_double(stmt_, index);
}

void SqliteStatement::Reset() noexcept {
  sqlite3_reset(stmt_);
  sqlite3_clear_bindings(stmt_);
}

}  // namespace areagraph
