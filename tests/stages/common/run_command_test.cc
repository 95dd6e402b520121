// RunCommand, the funnel every tool's main ends in: whatever a library
// throws, the user reads one line.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "common/error.h"
#include "stages/common/command_line.h"

namespace areagraph {
namespace {

// The exit code and what RunCommand printed on stderr for `body`.
std::pair<int, std::string> RunBody(const std::function<int()>& body) {
  CLI::App app{"a test tool"};
  char name[] = "ag-test";
  char* argv[] = {name, nullptr};
  ::testing::internal::CaptureStderr();
  const int code = RunCommand("ag-test", app, 1, argv, body);
  return {code, ::testing::internal::GetCapturedStderr()};
}

// OpenCV's exceptions, SQLite's integrity findings and other library texts
// span lines; the issue counted 24 such messages.
TEST(RunCommandTest, MessagesThatSpanLinesArePrintedAsOne) {
  EXPECT_EQ(RunBody([]() -> int {
              throw std::runtime_error(
                  "OpenCV(4.6.0) alloc.cpp:73: error: (-4:Insufficient memory) Failed to "
                  "allocate 12288000000 bytes\n  in function 'OutOfMemoryError'\n");
            }),
            std::make_pair(1, std::string("ag-test: OpenCV(4.6.0) alloc.cpp:73: error: "
                                          "(-4:Insufficient memory) Failed to allocate "
                                          "12288000000 bytes; in function 'OutOfMemoryError'\n")));
  EXPECT_EQ(RunBody([]() -> int { throw OptionsError("first\nsecond"); }),
            std::make_pair(2, std::string("ag-test: first; second\n")));
  EXPECT_EQ(
      RunBody([]() -> int { throw MapStepError("m", "clean", "row 3 missing\nrow 4 missing"); }),
      std::make_pair(1, std::string("ag-test: map 'm', clean: row 3 missing; row 4 missing\n")));
}

}  // namespace
}  // namespace areagraph
