#include "store/sqlite_transaction.h"

namespace areagraph {

SqliteTransaction::SqliteTransaction(sqlite3* db, SqliteStatement& begin, SqliteStatement& commit,
                                     SqliteStatement& rollback)
    : db_(db), commit_(commit), rollback_(rollback) {
  StatementUse use(begin);
  begin.Step();
}

SqliteTransaction::~SqliteTransaction() {
  // SQLite may already have rolled back by itself (e.g. on a full disk).
  if (committed_ || sqlite3_get_autocommit(db_)) return;
  StatementUse use(rollback_);
  try {
    rollback_.Step();
  } catch (...) {
    // Nothing more to do: the connection closes the transaction when it ends.
  }
}

void SqliteTransaction::Commit() {
  StatementUse use(commit_);
  commit_.Step();
  committed_ = true;
}

}  // namespace areagraph
