// A new store file made whole before it gets its name.
//
// SQLite's own way to a new WAL store costs six syncs: switching the empty
// file to WAL goes through a rollback journal (journal, directory, journal
// again, file) and the schema's commit starts a log (its header and the
// directory), about 2 ms each here, a tenth of a small map's ag-run. Here the
// file is built under a temporary name without journal or syncs, synced once
// and linked to its name, which fails if someone else made the store
// meanwhile. A crash before the link leaves no store (and a stray temporary
// file); after it the store is whole. The directory entry is synced by the
// first writer, whose new log syncs the directory anyway; until then the
// store holds nothing a power cut could lose.

#include "store/sqlite_store_creation.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <exception>
#include <string>

#include "store/sqlite_artifact_store.h"

namespace areagraph {
namespace store_internal {
namespace {

// The temporary file and what SQLite may leave beside it.
void RemoveTemporary(const std::string& temporary) {
  for (const char* suffix : {"", "-wal", "-shm", "-journal"}) {
    unlink((temporary + suffix).c_str());
  }
}

bool SyncFileData(const std::string& path) {
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool synced = fdatasync(fd) == 0;
  close(fd);
  return synced;
}

}  // namespace

}  // namespace store_internal

bool CreateNewStoreFile(const std::string& path) {
  if (path.empty() || path == kMemoryStorePath) return false;
  struct stat info {};
  if (lstat(path.c_str(), &info) == 0 || errno != ENOENT) return false;  // an empty file too
  static std::atomic<int> serial{0};
  const std::string temporary =
      path + ".new-" + std::to_string(getpid()) + "-" + std::to_string(serial++);
  // Any failure leaves the work to the ordinary open, which reports it.
  const int fd = open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) return false;
  close(fd);
  try {
    SqliteArtifactStore::BuildUnpublishedFile(temporary);
  } catch (const std::exception&) {
    store_internal::RemoveTemporary(temporary);
    return false;
  }
  // On a link error other than EEXIST (a file system without hard links)
  // the ordinary open creates the store instead.
  const bool made =
      store_internal::SyncFileData(temporary) && link(temporary.c_str(), path.c_str()) == 0;
  store_internal::RemoveTemporary(temporary);
  return made;
}

void store_internal::CreateMissingStoreFile(const std::string& path) { CreateNewStoreFile(path); }

}  // namespace areagraph
