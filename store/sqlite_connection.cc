#include "store/sqlite_connection.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "common/error.h"
#include "common/protected_files.h"

namespace areagraph {
namespace {

bool FileExists(const std::string& path) {
  struct stat info;
  return stat(path.c_str(), &info) == 0;
}

// Why `path` could not be opened, in words. Asked of the OS directly:
// SQLite's errno is that of its last fallback attempt, not of the real cause.
std::string OpenFailureReason(sqlite3* db, int rc, const std::string& path) {
  const std::filesystem::path parent = std::filesystem::absolute(path).parent_path();
  std::error_code ignored;
  if (!std::filesystem::is_directory(parent, ignored)) {
    return "directory '" + parent.string() + "' does not exist";
  }
  if (!FileExists(path) && access(parent.c_str(), W_OK | X_OK) != 0) {
    return "directory '" + parent.string() + "' is not writable (" + std::strerror(errno) + ")";
  }
  if (FileExists(path) && access(path.c_str(), R_OK) != 0) return std::strerror(errno);
  const int system_errno = db != nullptr ? sqlite3_system_errno(db) : 0;
  if (system_errno != 0) return std::strerror(system_errno);
  return db != nullptr ? sqlite3_errmsg(db) : sqlite3_errstr(rc);
}

}  // namespace

SqliteConnection::SqliteConnection(const std::string& path, StoreMode mode) {
  const bool memory = path == kMemoryStorePath;
  const bool read_only = mode == StoreMode::kReadOnly && !memory;
  if (read_only && !FileExists(path)) throw StoreError("store '" + path + "' does not exist");
  const int flags = read_only ? SQLITE_OPEN_READONLY : SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE;
  const bool existed = memory || FileExists(path);
  const int rc = sqlite3_open_v2(path.c_str(), &db_, flags, nullptr);
  if (rc != SQLITE_OK) {
    const std::string reason = OpenFailureReason(db_, rc, path);
    sqlite3_close_v2(db_);
    throw StoreError(std::string(existed ? "cannot open" : "cannot create") + " store '" + path +
                     "': " + reason);
  }
  if (!memory) ProtectStoreFile(path);
}

SqliteConnection::~SqliteConnection() { sqlite3_close_v2(db_); }

}  // namespace areagraph
