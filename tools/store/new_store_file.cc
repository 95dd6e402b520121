#include "tools/store/new_store_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>

#include "common/error.h"
#include "stages/common/output_file.h"

namespace areagraph {
namespace {

void RemoveStoreFiles(const std::string& path) {
  for (const char* suffix : {"", "-wal", "-shm", "-journal"}) {
    ::unlink((path + suffix).c_str());
  }
}

std::string TemporaryBeside(const std::string& path) {
  const std::filesystem::path target(path);
  const std::filesystem::path folder = target.has_parent_path() ? target.parent_path() : ".";
  return (folder / ("." + target.filename().string() + "." + std::to_string(::getpid()) + ".tmp"))
      .string();
}

}  // namespace

bool NothingAt(const std::string& path) {
  struct stat info;
  return ::lstat(path.c_str(), &info) != 0 && errno == ENOENT;
}

void CreateStoreFile(const std::string& path,
                     const std::function<void(const std::string& temporary)>& fill) {
  if (!NothingAt(path)) {
    throw StoreError("'" + path + "' already exists; name a new file");
  }
  const std::string temporary = TemporaryBeside(path);
  RemoveStoreFiles(temporary);  // left by a killed run of this process id
  try {
    fill(temporary);
    // link(2) never replaces; file systems without hard links get rename(2).
    if (::link(temporary.c_str(), path.c_str()) != 0) {
      const int code = errno;
      if (code == EEXIST) throw StoreError("'" + path + "' appeared meanwhile; it was left alone");
      if (code != EPERM && code != ENOTSUP && code != EOPNOTSUPP && code != EXDEV) {
        throw StoreError("cannot create '" + path + "': " + ErrnoText(code));
      }
      if (::rename(temporary.c_str(), path.c_str()) != 0) {
        throw StoreError("cannot create '" + path + "': " + ErrnoText(errno));
      }
    }
  } catch (...) {
    RemoveStoreFiles(temporary);
    throw;
  }
  RemoveStoreFiles(temporary);
}

}  // namespace areagraph
