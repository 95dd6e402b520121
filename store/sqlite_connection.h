#pragma once

#include <sqlite3.h>

#include <string>

#include "store/artifact_store.h"

namespace areagraph {

// The path that gives a private in-memory store.
inline constexpr char kMemoryStorePath[] = ":memory:";

// How a store opened read-only is read. SQLite reads a store in WAL mode
// through its -shm index beside it, which it creates when missing, and a
// read-only connection leaves that file and an empty -wal behind.
enum class ReadAccess {
  // The user could write the file and its folder: a read-write connection
  // with `PRAGMA query_only`, so that SQLite's close removes the side files
  // (folding any log first) when it is the last connection, as after a
  // writer. Concurrent writers are seen as with any reader.
  kQueryOnly,
  // Cannot write the file, but the -shm exists or the folder is writable:
  // a read-only connection through the shared index (concurrent writers are
  // seen; side files it had to create stay).
  kReadOnly,
  // The folder cannot be written (a read-only disk, another user's folder)
  // and there is no -shm: SQLite's `immutable=1`, which reads the file
  // alone without locks or side files. Right for a store nobody writes,
  // which is the case here: a writer must create the -wal and -shm in that
  // folder, so none was active when the store was opened. One that starts
  // afterwards is not seen, and its fold may make this reader fail with
  // "database disk image is malformed"; it never makes it write.
  kImmutable,
};

// The access to use for `path`, an existing file. Throws StoreError when a
// log of unfolded commits lies beside it that cannot be read (the folder is
// not writable and has no -shm): reading the file alone would give an old state.
ReadAccess ChooseReadAccess(const std::string& path);

// The URI that opens `path` with `access` (this SQLite build interprets URIs).
std::string StoreUri(const std::string& path, ReadAccess access);

// Owns the SQLite connection of one store. Opening reads nothing of the file
// yet, so a bad file is recognized later without having been changed. Throws
// StoreError when the file cannot be opened or created, and in read-only mode
// when it does not exist (read-only never creates a file; ChooseReadAccess
// says how it reads). ":memory:" is always opened read-write: it is private
// and there is no file to protect. A store file that opens is protected from
// the process's own outputs (ProtectStoreFile).
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
