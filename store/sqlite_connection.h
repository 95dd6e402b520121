#pragma once

#include <sqlite3.h>

#include <string>

#include "store/artifact_store.h"

namespace areagraph {

// The path that gives a private in-memory store.
inline constexpr char kMemoryStorePath[] = ":memory:";

// Owns the SQLite connection of one store. Opening reads nothing of the file
// yet, so a bad file is recognized later without having been changed. Throws
// StoreError when the file cannot be opened or created, and in read-only mode
// when it does not exist (read-only never creates a file). ":memory:" is
// always opened read-write: it is private and there is no file to protect.
// A store file that opens is protected from the process's own outputs
// (ProtectStoreFile).
class SqliteConnection {
 public:
  SqliteConnection(const std::string& path, StoreMode mode);
  ~SqliteConnection();
  SqliteConnection(const SqliteConnection&) = delete;
  SqliteConnection& operator=(const SqliteConnection&) = delete;

  sqlite3* get() const { return db_; }

 private:
  sqlite3* db_ = nullptr;
};

}  // namespace areagraph
