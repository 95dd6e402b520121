#include "stages/common/output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <optional>

#include "common/error.h"
#include "common/protected_files.h"

namespace areagraph {
namespace {

// Thrown inside this file with the reason only; WriteOutputFile adds the target.
struct WriteFailure {
  std::string reason;
};

[[noreturn]] void Fail(const std::string& reason) { throw WriteFailure{reason}; }
[[noreturn]] void FailWithErrno(int code) { Fail(ErrnoText(code)); }

// Closes a descriptor once, also when an exception leaves the scope.
class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }
  // Closes now and reports the error a delayed write may surface only here.
  void Close() {
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0 && errno != EINTR) FailWithErrno(errno);
  }

 private:
  int fd_;
};

// write(2) until every byte is out, retrying interrupted and partial writes.
void WriteAll(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t written = ::write(fd, bytes.data(), bytes.size());
    if (written < 0) {
      if (errno == EINTR) continue;
      FailWithErrno(errno);
    }
    if (written == 0) Fail("the write made no progress");
    bytes.remove_prefix(static_cast<size_t>(written));
  }
}

std::string ParentFolder(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

std::string BaseName(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// Why a file cannot be created in `folder`, in words.
std::string CreateFailureReason(int code, const std::string& folder) {
  if (code == ENOENT || code == ENOTDIR) return "folder '" + folder + "' does not exist";
  if (code == EACCES || code == EPERM) return "folder '" + folder + "' is not writable";
  return ErrnoText(code);
}

// A new file beside `path` that no one else uses: ".<name>.<pid>.<n>.tmp".
// Mode 0666 less the umask, as the shell would create the file.
std::string CreateTemporaryBeside(const std::string& path, int* fd) {
  static std::atomic<int> counter{0};
  const std::string folder = ParentFolder(path);
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string temporary = folder + "/." + BaseName(path) + "." +
                                  std::to_string(::getpid()) + "." + std::to_string(counter++) +
                                  ".tmp";
    *fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (*fd >= 0) return temporary;
    if (errno != EEXIST) Fail(CreateFailureReason(errno, folder));
  }
  Fail("cannot find a free temporary name in '" + folder + "'");
}

// Replaces (or creates) the regular file `path` through a temporary file and
// rename(2). `existing` is the file being replaced, if any.
void ReplaceRegularFile(const std::string& path, const std::optional<struct stat>& existing,
                        std::string_view bytes) {
  if (const std::optional<std::string> reason = ProtectedFileReason(path)) Fail(*reason);
  if (existing && ::access(path.c_str(), W_OK) != 0) FailWithErrno(errno);
  int raw_fd = -1;
  const std::string temporary = CreateTemporaryBeside(path, &raw_fd);
  Descriptor fd(raw_fd);
  try {
    if (existing) {
      // Keep what the replaced file had; the owner only root can keep.
      if (::fchmod(fd.get(), existing->st_mode & 07777) != 0) FailWithErrno(errno);
      if (::geteuid() == 0) (void)!::fchown(fd.get(), existing->st_uid, existing->st_gid);
    }
    WriteAll(fd.get(), bytes);
    if (::fsync(fd.get()) != 0) FailWithErrno(errno);
    fd.Close();
    if (::rename(temporary.c_str(), path.c_str()) != 0) FailWithErrno(errno);
  } catch (...) {
    ::unlink(temporary.c_str());
    throw;
  }
}

// Writes into an existing FIFO or character device, which must stay what it is.
void WriteIntoSpecialFile(const std::string& path, std::string_view bytes) {
  Descriptor fd(::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY));
  if (fd.get() < 0) FailWithErrno(errno);
  WriteAll(fd.get(), bytes);
  fd.Close();
}

void WriteStandardOutput(std::string_view bytes) {
  // What the tool printed before must come first.
  std::cout.flush();
  if (std::fflush(stdout) != 0) FailWithErrno(errno);
  WriteAll(STDOUT_FILENO, bytes);
}

// The file a symbolic link leads to, all links resolved; nullopt when the
// kernel gives no name for it (a /proc/self/fd link to a pipe).
std::optional<std::string> ResolvedPath(const std::string& path) {
  char resolved[PATH_MAX];
  if (::realpath(path.c_str(), resolved) == nullptr) return std::nullopt;
  return std::string(resolved);
}

void WriteFollowingLinks(const std::string& target, std::string_view bytes) {
  struct stat link_info;
  if (::lstat(target.c_str(), &link_info) != 0) {
    if (errno != ENOENT) FailWithErrno(errno);
    return ReplaceRegularFile(target, std::nullopt, bytes);  // a new file
  }
  struct stat info = link_info;
  const bool is_link = S_ISLNK(link_info.st_mode);
  if (is_link && ::stat(target.c_str(), &info) != 0) {
    if (errno == ENOENT) Fail("it is a symbolic link to a file that does not exist");
    FailWithErrno(errno);
  }
  if (S_ISREG(info.st_mode)) {
    if (!is_link) return ReplaceRegularFile(target, info, bytes);
    const std::optional<std::string> resolved = ResolvedPath(target);
    if (resolved) return ReplaceRegularFile(*resolved, info, bytes);
    return WriteIntoSpecialFile(target, bytes);  // unnamed: write through the link
  }
  if (S_ISFIFO(info.st_mode) || S_ISCHR(info.st_mode)) return WriteIntoSpecialFile(target, bytes);
  if (S_ISDIR(info.st_mode)) Fail("it is a folder");
  if (S_ISBLK(info.st_mode)) Fail("it is a block device; areagraph does not write into disks");
  if (S_ISSOCK(info.st_mode)) Fail("it is a socket; use --out - for standard output");
  Fail("it is not a file that can be written");
}

}  // namespace

std::string ErrnoText(int code) {
  std::string text = std::strerror(code);
  if (!text.empty()) text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
  return text;
}

bool IsStandardOutput(const std::string& target) { return target == kStandardOutputName; }

void WriteOutputFile(const std::string& target, std::string_view bytes) {
  if (target.empty()) throw InputError("cannot write to an empty file name");
  try {
    if (IsStandardOutput(target)) return WriteStandardOutput(bytes);
    WriteFollowingLinks(target, bytes);
  } catch (const WriteFailure& failure) {
    const std::string name = IsStandardOutput(target) ? "to standard output" : "'" + target + "'";
    throw InputError("cannot write " + name + ": " + failure.reason);
  }
}

void FlushStandardOutput() {
  // stdio first: std::cout writes through it (synced with stdio), and its
  // flush would use up the errno of the failing write.
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  const int code = errno;
  std::cout.flush();
  if (flushed && !std::ferror(stdout) && std::cout.good()) return;
  std::clearerr(stdout);
  throw Error("cannot write to standard output: " +
              (code != 0 ? ErrnoText(code) : std::string("part of the output was lost")));
}

}  // namespace areagraph
