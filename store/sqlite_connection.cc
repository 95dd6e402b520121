#include "store/sqlite_connection.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>

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

bool CanWrite(const std::string& path) { return access(path.c_str(), W_OK) == 0; }

int64_t FileBytes(const std::string& path) {
  struct stat info;
  return stat(path.c_str(), &info) == 0 ? static_cast<int64_t>(info.st_size) : -1;
}

}  // namespace

ReadAccess ChooseReadAccess(const std::string& path) {
  const std::string folder = std::filesystem::absolute(path).parent_path().string();
  const bool folder_writable = access(folder.c_str(), W_OK | X_OK) == 0;
  if (folder_writable && CanWrite(path)) return ReadAccess::kQueryOnly;
  if (folder_writable || FileExists(path + "-shm")) return ReadAccess::kReadOnly;
  if (FileBytes(path + "-wal") > 0) {
    throw StoreError("store '" + path +
                     "' has a write-ahead log of commits not yet folded into it, which cannot be "
                     "read without writing its folder; let its owner open it once (ag-store "
                     "verify) to fold it");
  }
  return ReadAccess::kImmutable;
}

std::string StoreUri(const std::string& path, ReadAccess access) {
  std::string uri = "file:";
  for (const unsigned char c : path) {
    if (std::isalnum(c) || c == '/' || c == '.' || c == '_' || c == '-' || c == '~') {
      uri += static_cast<char>(c);
    } else {
      char escaped[4];
      std::snprintf(escaped, sizeof(escaped), "%%%02X", c);
      uri += escaped;
    }
  }
  switch (access) {
    case ReadAccess::kQueryOnly:
      return uri;
    case ReadAccess::kReadOnly:
      return uri + "?mode=ro";
    case ReadAccess::kImmutable:
      return uri + "?mode=ro&immutable=1";
  }
  return uri;
}

SqliteConnection::SqliteConnection(const std::string& path, StoreMode mode) {
  const bool memory = path == kMemoryStorePath;
  const bool read_only = mode == StoreMode::kReadOnly && !memory;
  if (read_only && !FileExists(path)) throw StoreError("store '" + path + "' does not exist");
  const std::optional<ReadAccess> access =
      read_only ? std::optional<ReadAccess>(ChooseReadAccess(path)) : std::nullopt;
  const bool existed = memory || FileExists(path);
  const int rc = access
                     ? sqlite3_open_v2(StoreUri(path, *access).c_str(), &db_,
                                       (*access == ReadAccess::kQueryOnly ? SQLITE_OPEN_READWRITE
                                                                          : SQLITE_OPEN_READONLY) |
                                           SQLITE_OPEN_URI,
                                       nullptr)
                     : sqlite3_open_v2(path.c_str(), &db_,
                                       SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr);
  if (rc != SQLITE_OK) {
    const std::string reason = OpenFailureReason(db_, rc, path);
    sqlite3_close_v2(db_);
    db_ = nullptr;
    throw StoreError(std::string(existed ? "cannot open" : "cannot create") + " store '" + path +
                     "': " + reason);
  }
  if (access == ReadAccess::kQueryOnly &&
      sqlite3_exec(db_, "PRAGMA query_only = ON", nullptr, nullptr, nullptr) != SQLITE_OK) {
    sqlite3_close_v2(db_);
    db_ = nullptr;
    throw StoreError("cannot open store '" + path + "' for reading only");
  }
  if (!memory) ProtectStoreFile(path);
}

SqliteConnection::~SqliteConnection() { sqlite3_close_v2(db_); }

}  // namespace areagraph
