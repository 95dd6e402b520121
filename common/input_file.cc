#include "common/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>

#include "common/error.h"
#include "common/file_descriptor.h"

namespace areagraph {
namespace {

std::string KindOf(mode_t mode) {
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "";
}

std::string Reason(int code) {
  std::string text = std::strerror(code);
  if (!text.empty()) text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
  return text;
}

}  // namespace

std::string SpecialFileKind(const std::string& path) {
  struct stat info;
  if (::stat(path.c_str(), &info) != 0) return "";
  return KindOf(info.st_mode);
}

std::string ReadInputFile(const std::string& path, const std::string& what, size_t max_bytes) {
  const auto fail = [&](const std::string& reason) {
    return InputError("cannot read " + what + ": " + reason);
  };
  if (path.find('\0') != std::string::npos) throw fail("its name holds a NUL byte");
  // O_NONBLOCK: opening a FIFO for reading would wait for a writer.
  const FileDescriptor fd(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY));
  if (fd.get() < 0) throw fail(errno == ENOENT ? "it does not exist" : Reason(errno));
  struct stat info;
  if (::fstat(fd.get(), &info) != 0) throw fail(Reason(errno));
  if (S_ISDIR(info.st_mode)) throw fail("it is a directory");
  if (!S_ISREG(info.st_mode)) throw fail("it is " + KindOf(info.st_mode) + ", not a regular file");
  std::string bytes;
  bytes.reserve(std::min(static_cast<size_t>(info.st_size), max_bytes));
  char chunk[1 << 16];
  while (bytes.size() < max_bytes) {
    const ssize_t got = ::read(fd.get(), chunk, std::min(sizeof(chunk), max_bytes - bytes.size()));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw fail(Reason(errno));
    if (got == 0) break;
    bytes.append(chunk, static_cast<size_t>(got));
  }
  return bytes;
}

}  // namespace areagraph
