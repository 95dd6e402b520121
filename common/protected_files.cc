#include "common/protected_files.h"

#include <sys/stat.h>

#include <climits>
#include <cstdlib>
#include <mutex>
#include <utility>
#include <vector>

namespace areagraph {
namespace {

struct ProtectedName {
  std::string canonical_path;
  std::string reason;
};

struct ProtectedFiles {
  std::mutex mutex;
  std::vector<ProtectedName> names;
};

ProtectedFiles& Registry() {
  static ProtectedFiles* registry = new ProtectedFiles;  // never destroyed: used until exit
  return *registry;
}

std::string RealPath(const std::string& path) {
  char resolved[PATH_MAX];
  if (::realpath(path.c_str(), resolved) == nullptr) return {};
  return resolved;
}

// The absolute name `path` stands for, every symbolic link resolved; for a
// file that does not exist yet, its resolved folder and its own name.
std::string CanonicalName(const std::string& path) {
  std::string resolved = RealPath(path);
  if (!resolved.empty()) return resolved;
  const size_t slash = path.find_last_of('/');
  const std::string folder =
      slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  if (name.empty() || name == "." || name == "..") return {};
  resolved = RealPath(folder);
  if (resolved.empty()) return {};
  return (resolved == "/" ? "" : resolved) + "/" + name;
}

}  // namespace

void ProtectStoreFile(const std::string& path) {
  const std::string store = CanonicalName(path);
  if (store.empty()) return;  // an unreachable folder: nothing can be written there either
  const std::string quoted = "'" + path + "'";
  std::vector<ProtectedName> names = {
      {store, "it is the store " + quoted},
      {store + "-wal", "it is the write-ahead log of the store " + quoted},
      {store + "-shm", "it is the shared-memory file of the store " + quoted},
      {store + "-journal", "it is the journal of the store " + quoted},
  };
  ProtectedFiles& registry = Registry();
  const std::lock_guard<std::mutex> lock(registry.mutex);
  for (ProtectedName& name : names) {
    bool known = false;
    for (const ProtectedName& existing : registry.names) {
      known = known || existing.canonical_path == name.canonical_path;
    }
    if (!known) registry.names.push_back(std::move(name));
  }
}

std::optional<std::string> ProtectedFileReason(const std::string& path) {
  const std::string target = CanonicalName(path);
  if (target.empty()) return std::nullopt;
  struct stat target_info;
  const bool target_exists = ::stat(target.c_str(), &target_info) == 0;
  ProtectedFiles& registry = Registry();
  const std::lock_guard<std::mutex> lock(registry.mutex);
  for (const ProtectedName& name : registry.names) {
    if (name.canonical_path == target) return name.reason;
    // The same file under another name (a bind mount, a hard link).
    struct stat info;
    if (target_exists && ::stat(name.canonical_path.c_str(), &info) == 0 &&
        info.st_dev == target_info.st_dev && info.st_ino == target_info.st_ino) {
      return name.reason;
    }
  }
  return std::nullopt;
}

}  // namespace areagraph
