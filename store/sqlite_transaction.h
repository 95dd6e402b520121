#pragma once

#include <sqlite3.h>

#include "store/sqlite_statement.h"

namespace areagraph {

// One write transaction: BEGIN IMMEDIATE on construction, so concurrent
// writers queue up through the busy timeout instead of failing halfway, and
// ROLLBACK on destruction unless Commit() ran. A process killed in between
// leaves the store as it was, which SQLite's journal guarantees.
class SqliteTransaction {
 public:
  SqliteTransaction(sqlite3* db, SqliteStatement& begin, SqliteStatement& commit,
                    SqliteStatement& rollback);
  ~SqliteTransaction();
  SqliteTransaction(const SqliteTransaction&) = delete;
  SqliteTransaction& operator=(const SqliteTransaction&) = delete;

  void Commit();

 private:
  sqlite3* db_;
  SqliteStatement& commit_;
  SqliteStatement& rollback_;
  bool committed_ = false;
};

}  // namespace areagraph
