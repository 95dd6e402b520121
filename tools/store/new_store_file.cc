#include "tools/store/new_store_file.h"

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <set>

#include "common/error.h"
#include "stages/common/output_file.h"

namespace areagraph {
namespace {

void RemoveStoreFiles(const std::string& path) {
  for (const char* suffix : {"", "-wal", "-shm", "-journal"}) {
    ::unlink((path + suffix).c_str());
  }
}

std::string HostName() {
  char name[256] = {};
  if (::gethostname(name, sizeof(name) - 1) != 0) return "host";
  std::string host(name);
  for (char& c : host) {
    if (c == '.' || c == '/') c = '_';  // keeps the temporary's name parseable
  }
  return host.empty() ? "host" : host;
}

// ".OUT.HOST.PID.tmp": hidden, and naming the process that writes it, so a
// later run can tell a killed run's file from a running one's. The host
// matters on a shared file system, where a process id says nothing about
// another machine's processes.
std::string TemporaryPrefix(const std::filesystem::path& target) {
  return "." + target.filename().string() + "." + HostName() + ".";
}

std::filesystem::path FolderOf(const std::filesystem::path& target) {
  return target.has_parent_path() ? target.parent_path() : ".";
}

std::string TemporaryBeside(const std::string& path) {
  const std::filesystem::path target(path);
  return (FolderOf(target) / (TemporaryPrefix(target) + std::to_string(::getpid()) + ".tmp"))
      .string();
}

// The temporaries of earlier runs for `path` on this host whose process is
// gone (killed: a finished run removes its own), with their -wal and -shm.
void RemoveStaleTemporaries(const std::string& path) {
  const std::filesystem::path target(path);
  const std::string prefix = TemporaryPrefix(target);
  std::set<std::string> stale;
  std::error_code error;
  for (std::filesystem::directory_iterator it(FolderOf(target), error), end; !error && it != end;
       it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const size_t dot = name.find('.', prefix.size());
    if (dot == std::string::npos || name.compare(dot, 4, ".tmp") != 0) continue;
    const std::string rest = name.substr(dot + 4);
    if (rest != "" && rest != "-wal" && rest != "-shm" && rest != "-journal") continue;
    const std::string pid_text = name.substr(prefix.size(), dot - prefix.size());
    if (pid_text.empty() || pid_text.find_first_not_of("0123456789") != std::string::npos ||
        pid_text.size() > 9) {
      continue;
    }
    const pid_t pid = static_cast<pid_t>(std::stol(pid_text));
    if (pid == ::getpid() || ::kill(pid, 0) == 0 || errno != ESRCH) continue;
    stale.insert((FolderOf(target) / name.substr(0, dot + 4)).string());
  }
  for (const std::string& temporary : stale) RemoveStoreFiles(temporary);
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
  RemoveStaleTemporaries(path);
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
