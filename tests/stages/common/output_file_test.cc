// WriteOutputFile against every kind of thing a user can name as --out: new
// paths, regular files, links, FIFOs, character devices (/dev/null,
// /dev/full), folders, block devices, sockets, and a disk that fills up.
// Whatever is not a regular file must still be what it was afterwards.
#include "stages/common/output_file.h"

#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <thread>

#include "common/error.h"
#include "common/protected_files.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::ErrorOf;
using testing::ReadFile;
using testing::TempDir;
using testing::WriteFile;

struct stat StatOf(const std::string& path) {
  struct stat info {};
  EXPECT_EQ(::lstat(path.c_str(), &info), 0) << path;
  return info;
}

// The names in `dir`, to show that no temporary file was left behind.
std::vector<std::string> Names(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string WriteError(const std::string& target, const std::string& bytes) {
  return ErrorOf<InputError>([&] { WriteOutputFile(target, bytes); });
}

TEST(OutputFileTest, NewFileGetsTheBytesAndTheUsualMode) {
  TempDir dir;
  const mode_t mask = ::umask(022);
  EXPECT_EQ(WriteError(dir.File("out.json"), "{}\n"), "");
  ::umask(mask);
  EXPECT_EQ(ReadFile(dir.File("out.json")), "{}\n");
  EXPECT_EQ(StatOf(dir.File("out.json")).st_mode & 0777, 0644u);
  EXPECT_EQ(Names(dir.path()), std::vector<std::string>{"out.json"});
}

TEST(OutputFileTest, RegularFileIsReplacedWholeAndKeepsItsMode) {
  TempDir dir;
  const std::string path = dir.File("out.png");
  WriteFile(path, std::string(10000, 'o'));
  ASSERT_EQ(::chmod(path.c_str(), 0640), 0);
  const ino_t old_inode = StatOf(path).st_ino;
  EXPECT_EQ(WriteError(path, "new"), "");
  EXPECT_EQ(ReadFile(path), "new");
  EXPECT_EQ(StatOf(path).st_mode & 07777, 0640u);
  // Renamed into place: a reader holding the old file never sees a mix.
  EXPECT_NE(StatOf(path).st_ino, old_inode);
  EXPECT_EQ(Names(dir.path()), std::vector<std::string>{"out.png"});
}

TEST(OutputFileTest, AFileCalledLikeTheOldTemporaryIsLeftAlone) {
  TempDir dir;
  WriteFile(dir.File("out.json.tmp"), "someone's data");
  EXPECT_EQ(WriteError(dir.File("out.json"), "{}"), "");
  EXPECT_EQ(ReadFile(dir.File("out.json.tmp")), "someone's data");
}

TEST(OutputFileTest, SymbolicLinksAreFollowedAndStayLinks) {
  TempDir dir;
  std::filesystem::create_directory(dir.File("real"));
  WriteFile(dir.File("real/target.png"), "old");
  std::filesystem::create_symlink("real/target.png", dir.File("link.png"));
  std::filesystem::create_symlink("link.png", dir.File("link_to_link.png"));
  EXPECT_EQ(WriteError(dir.File("link_to_link.png"), "new"), "");
  EXPECT_TRUE(S_ISLNK(StatOf(dir.File("link.png")).st_mode));
  EXPECT_TRUE(S_ISLNK(StatOf(dir.File("link_to_link.png")).st_mode));
  EXPECT_EQ(ReadFile(dir.File("real/target.png")), "new");
  EXPECT_EQ(Names(dir.File("real")), std::vector<std::string>{"target.png"});
}

TEST(OutputFileTest, LinkToNothingIsRefusedAndNothingIsCreated) {
  TempDir dir;
  std::filesystem::create_symlink("missing.png", dir.File("link.png"));
  EXPECT_EQ(WriteError(dir.File("link.png"), "x"),
            "cannot write '" + dir.File("link.png") +
                "': it is a symbolic link to a file that does not exist");
  EXPECT_EQ(Names(dir.path()), std::vector<std::string>{"link.png"});
}

TEST(OutputFileTest, FifoIsWrittenIntoAndStaysAFifo) {
  TempDir dir;
  const std::string fifo = dir.File("pipe");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = ReadFile(fifo); });
  const std::string bytes(200000, 'b');  // more than a pipe buffer holds
  EXPECT_EQ(WriteError(fifo, bytes), "");
  reader.join();
  EXPECT_EQ(received, bytes);
  EXPECT_TRUE(S_ISFIFO(StatOf(fifo).st_mode));
  EXPECT_EQ(Names(dir.path()), std::vector<std::string>{"pipe"});
}

TEST(OutputFileTest, DevNullAndLinksToItStayDevices) {
  TempDir dir;
  std::filesystem::create_symlink("/dev/null", dir.File("discard.png"));
  EXPECT_EQ(WriteError(dir.File("discard.png"), "x"), "");
  EXPECT_TRUE(S_ISLNK(StatOf(dir.File("discard.png")).st_mode));
  EXPECT_EQ(WriteError("/dev/null", "x"), "");
  EXPECT_TRUE(S_ISCHR(StatOf("/dev/null").st_mode));
}

TEST(OutputFileTest, DevFullSaysTheDiskIsFull) {
  EXPECT_EQ(WriteError("/dev/full", "x"), "cannot write '/dev/full': no space left on device");
  EXPECT_TRUE(S_ISCHR(StatOf("/dev/full").st_mode));
}

// Device nodes of our own, so that a broken writer could only replace those.
TEST(OutputFileTest, PrivateDeviceNodesStayDevices) {
  TempDir dir;
  if (::mknod(dir.File("null").c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0 ||
      ::mknod(dir.File("full").c_str(), S_IFCHR | 0666, makedev(1, 7)) != 0) {
    GTEST_SKIP() << "mknod needs CAP_MKNOD; /dev/null and /dev/full are covered above";
  }
  EXPECT_EQ(WriteError(dir.File("null"), "x"), "");
  EXPECT_NE(WriteError(dir.File("full"), "x").find("no space left on device"), std::string::npos);
  EXPECT_TRUE(S_ISCHR(StatOf(dir.File("null")).st_mode));
  EXPECT_TRUE(S_ISCHR(StatOf(dir.File("full")).st_mode));
  EXPECT_EQ(Names(dir.path()), (std::vector<std::string>{"full", "null"}));
}

TEST(OutputFileTest, BlockDeviceIsRefused) {
  TempDir dir;
  if (::mknod(dir.File("disk").c_str(), S_IFBLK | 0600, makedev(7, 0)) != 0) {
    GTEST_SKIP() << "mknod needs CAP_MKNOD";
  }
  EXPECT_EQ(WriteError(dir.File("disk"), "x"),
            "cannot write '" + dir.File("disk") +
                "': it is a block device; areagraph does not write into disks");
  EXPECT_TRUE(S_ISBLK(StatOf(dir.File("disk")).st_mode));
}

TEST(OutputFileTest, SocketIsRefused) {
  TempDir dir;
  const std::string path = dir.File("socket");
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  ASSERT_GE(fd, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  ASSERT_LT(path.size(), sizeof(address.sun_path));
  std::copy(path.begin(), path.end(), address.sun_path);
  ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)), 0);
  EXPECT_NE(WriteError(path, "x").find("it is a socket"), std::string::npos);
  EXPECT_TRUE(S_ISSOCK(StatOf(path).st_mode));
  ::close(fd);
}

TEST(OutputFileTest, FolderAndMissingFolderAreNamed) {
  TempDir dir;
  EXPECT_EQ(WriteError(dir.path(), "x"), "cannot write '" + dir.path() + "': it is a folder");
  EXPECT_EQ(WriteError(dir.File("no/such/out.json"), "x"),
            "cannot write '" + dir.File("no/such/out.json") + "': folder '" + dir.File("no/such") +
                "' does not exist");
  EXPECT_EQ(WriteError("", "x"), "cannot write to an empty file name");
}

// Root may write any file, so the check runs in a child that is "nobody".
TEST(OutputFileTest, ReadOnlyFileIsRefusedLikeTheShellWould) {
  TempDir dir;
  ASSERT_EQ(::chmod(dir.path().c_str(), 0777), 0);
  const std::string path = dir.File("keep.json");
  WriteFile(path, "old");
  ASSERT_EQ(::chmod(path.c_str(), 0444), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) ::_exit(2);
    const std::string error = WriteError(path, "new");
    ::_exit(error == "cannot write '" + path + "': permission denied" ? 0 : 1);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  if (WEXITSTATUS(status) == 2) GTEST_SKIP() << "cannot become nobody";
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_EQ(ReadFile(path), "old");
  EXPECT_EQ(Names(dir.path()), std::vector<std::string>{"keep.json"});
}

// Standard output is swapped for a file for the length of one write.
TEST(OutputFileTest, DashIsStandardOutput) {
  TempDir dir;
  std::fflush(stdout);
  const int saved = ::dup(STDOUT_FILENO);
  FILE* file = std::fopen(dir.File("stdout").c_str(), "w");
  ASSERT_NE(file, nullptr);
  ::dup2(::fileno(file), STDOUT_FILENO);
  std::printf("before ");
  const std::string error = WriteError("-", "bytes");
  std::fflush(stdout);
  ::dup2(saved, STDOUT_FILENO);
  ::close(saved);
  std::fclose(file);
  EXPECT_EQ(error, "");
  EXPECT_EQ(ReadFile(dir.File("stdout")), "before bytes");  // in order
  EXPECT_EQ(Names(dir.path()), std::vector<std::string>{"stdout"});
}

// A store the process opened, and the files SQLite keeps beside it, are never
// replaced, whichever name leads to them; other files beside it are written.
TEST(OutputFileTest, ProtectedStoreFilesAreRefusedByAnyName) {
  TempDir dir;
  std::filesystem::create_directory(dir.File("sub"));
  WriteFile(dir.File("guarded.db"), "store");
  ProtectStoreFile(dir.File("sub/../guarded.db"));
  std::filesystem::create_symlink(dir.File("guarded.db"), dir.File("link"));
  const std::string refused = "': it is the store '" + dir.File("sub/../guarded.db") + "'";
  EXPECT_EQ(WriteError(dir.File("guarded.db"), "x"),
            "cannot write '" + dir.File("guarded.db") + refused);
  EXPECT_EQ(WriteError(dir.File("sub/../guarded.db"), "x"),
            "cannot write '" + dir.File("sub/../guarded.db") + refused);
  EXPECT_EQ(WriteError(dir.File("link"), "x"), "cannot write '" + dir.File("link") + refused);
  EXPECT_NE(WriteError(dir.File("guarded.db-wal"), "x").find("write-ahead log of the store"),
            std::string::npos);
  EXPECT_NE(WriteError(dir.File("guarded.db-shm"), "x").find("shared-memory file"),
            std::string::npos);
  EXPECT_NE(WriteError(dir.File("guarded.db-journal"), "x").find("journal of the store"),
            std::string::npos);
  EXPECT_EQ(ReadFile(dir.File("guarded.db")), "store");
  EXPECT_TRUE(std::filesystem::is_symlink(dir.File("link")));
  EXPECT_EQ(WriteError(dir.File("guarded.db.json"), "x"), "");
  EXPECT_EQ(ReadFile(dir.File("guarded.db.json")), "x");
}

TEST(OutputFileTest, ErrnoTextIsLowerCase) {
  EXPECT_EQ(ErrnoText(ENOSPC), "no space left on device");
  EXPECT_EQ(ErrnoText(EACCES), "permission denied");
}

}  // namespace
}  // namespace areagraph
