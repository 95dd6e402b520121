#pragma once

#include <sqlite3.h>

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

namespace areagraph {

// How long a store waits for another process's write lock before giving up.
constexpr int kStoreBusyTimeoutMs = 10000;

// SQLite's reason for `rc` in words: the system's for a failed system call
// ("no space left on device"), else the connection's message when it belongs
// to this error, else SQLite's text for the code.
std::string SqliteReason(sqlite3* db, int rc);

// Throws StoreError unless `rc` is SQLITE_OK, SQLITE_ROW or SQLITE_DONE. Every
// SQLite return code of the store goes through here, so each failure reads the
// same way: the store path, SQLite's reason and what the store was doing.
void CheckSqlite(sqlite3* db, const std::string& store_path, int rc, const std::string& action);

// One statement, prepared once and finalized when the store closes. `action` names what the
// statement is for ("reading the head") and ends up in every error it raises. The bind and column
// helpers check types, so a hand-edited store gives a clear error instead of wrong values.
class SqliteStatement {
 public:
  SqliteStatement(sqlite3* db, const std::string& store_path, const char* sql, std::string action);
  ~SqliteStatement();
  SqliteStatement(const SqliteStatement&) = delete;
  SqliteStatement& operator=(const SqliteStatement&) = delete;

  void BindText(int index, std::string_view text);
  void BindBlob(int index, std::string_view bytes);
  // Binds `bytes` without SQLite's copy (a stage's payload frame is tens of
  // MB); they must stay alive until the statement is reset.
  void BindBlobUncopied(int index, std::string_view bytes);
  void BindInt64(int index, int64_t value);
  void BindDouble(int index, double value);

  // Runs the statement one step: true when a row is ready, false when done.
  bool Step();

  // Column readers; `column` is the name used in error messages.
  std::string ColumnText(int index, const char* column) const;
  std::string ColumnBlob(int index, const char* column) const;
  // The BLOB without a copy; valid until the next Step or Reset.
  std::string_view ColumnBlobView(int index, const char* column) const;
  int64_t ColumnInt64(int index, const char* column) const;
  double ColumnDouble(int index, const char* column) const;

  // Resets the statement and clears its bindings; never throws.
  void Reset() noexcept;

 private:
  // BindBlob with SQLite's lifetime flag (SQLITE_TRANSIENT or SQLITE_STATIC).
  void BindBlobWith(int index, std::string_view bytes, void (*lifetime)(void*));
  void Check(int rc) const;
  void CheckColumnType(int index, const char* column, int expected, const char* expected_name,
                       int also_allowed = -1) const;

  sqlite3* db_;
  std::string store_path_;
  std::string action_;
  sqlite3_stmt* stmt_ = nullptr;
};

// Resets a statement when one use of it ends, also when an exception leaves
// the scope, so the next use starts clean and no read snapshot stays open.
class StatementUse {
 public:
  explicit StatementUse(SqliteStatement& statement) : statement_(statement) {}
  ~StatementUse() { statement_.Reset(); }
  StatementUse(const StatementUse&) = delete;
  StatementUse& operator=(const StatementUse&) = delete;

 private:
  SqliteStatement& statement_;
};

// A statement of the store prepared on its first use, not when the store
// opens: a process uses a few of the store's two dozen statements (ag-run's
// runner two or three, ag-render one), and preparing them all cost about
// 2 M instructions per open. A preparation error is raised at that first use,
// with the statement's `action`. Empty (false) for a statement that the open
// store's schema does not have.
class LazyStatement {
 public:
  LazyStatement() = default;
  LazyStatement(sqlite3* db, const std::string& store_path, const char* sql, std::string action)
      : db_(db), store_path_(&store_path), sql_(sql), action_(std::move(action)) {}

  explicit operator bool() const { return sql_ != nullptr; }
  // The statement, prepared now if it was not yet; must not be empty.
  SqliteStatement& operator*() const;
  SqliteStatement* operator->() const { return &**this; }
  bool prepared() const { return statement_ != nullptr; }

 private:
  sqlite3* db_ = nullptr;
  const std::string* store_path_ = nullptr;  // the store's, which outlives this
  const char* sql_ = nullptr;                // a string literal
  std::string action_;
  mutable std::unique_ptr<SqliteStatement> statement_;
};

}  // namespace areagraph
