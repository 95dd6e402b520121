// ReadInputFile: regular files are read; a FIFO without a writer, a device,
// a folder and a name with a NUL byte are refused at once, never waited on.
#include "common/input_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <string>

#include "common/error.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::ErrorOf;

TEST(InputFileTest, RegularFileIsReadWholeOrUpToALimit) {
  testing::TempDir dir;
  const std::string path = dir.File("o.pbtxt");
  testing::WriteFile(path, std::string("abc\0def", 7));
  EXPECT_EQ(ReadInputFile(path, "options file"), std::string("abc\0def", 7));
  EXPECT_EQ(ReadInputFile(path, "options file", 2), "ab");
  testing::WriteFile(dir.File("empty"), "");
  EXPECT_EQ(ReadInputFile(dir.File("empty"), "it"), "");
}

// The hang: opening a FIFO without a writer waited for ever.
TEST(InputFileTest, FifoWithoutAWriterIsRefusedAtOnce) {
  testing::TempDir dir;
  const std::string fifo = dir.File("pipe.png");
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(ErrorOf<InputError>([&] { ReadInputFile(fifo, "image 'pipe.png'"); }),
            "cannot read image 'pipe.png': it is a FIFO (named pipe), not a regular file");
  EXPECT_EQ(SpecialFileKind(fifo), "a FIFO (named pipe)");
}

TEST(InputFileTest, OtherFilesThatAreNotRegularAreRefused) {
  testing::TempDir dir;
  EXPECT_EQ(ErrorOf<InputError>([&] { ReadInputFile("/dev/zero", "map"); }),
            "cannot read map: it is a character device, not a regular file");
  EXPECT_EQ(ErrorOf<InputError>([&] { ReadInputFile(dir.path(), "map"); }),
            "cannot read map: it is a directory");
  EXPECT_EQ(ErrorOf<InputError>([&] { ReadInputFile(dir.File("none"), "map"); }),
            "cannot read map: it does not exist");
  EXPECT_EQ(SpecialFileKind("/dev/null"), "a character device");
  EXPECT_EQ(SpecialFileKind(dir.path()), "");
  EXPECT_EQ(SpecialFileKind(dir.File("none")), "");
}

// "map.png\0.txt" would open map.png: the system ends a name at its NUL.
TEST(InputFileTest, NameWithANulByteIsRefused) {
  testing::TempDir dir;
  testing::WriteFile(dir.File("map.png"), "bytes");
  const std::string name = dir.File("map.png") + std::string("\0.txt", 5);
  EXPECT_EQ(ErrorOf<InputError>([&] { ReadInputFile(name, "image"); }),
            "cannot read image: its name holds a NUL byte");
}

}  // namespace
}  // namespace areagraph
