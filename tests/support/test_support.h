#pragma once

#include <cstdint>
#include <exception>
#include <string>
#include <vector>

namespace areagraph::testing {

// A fresh directory under the system temp dir, removed with its contents on
// destruction.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::string& path() const { return path_; }
  std::string File(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

// What a finished command did.
struct CommandResult {
  int exit_code = -1;  // -1 when killed by a signal
  int signal = 0;
  std::string out;
  std::string err;
};

// The folder of the executables under test: build/bin, or $AG_TEST_BIN_DIR
// (to run a test against another build, e.g. the code before a fix).
std::string BinDir();

// Runs <BinDir()>/<tool> with `args` (no shell), capturing stdout and stderr.
CommandResult RunTool(const std::string& tool, const std::vector<std::string>& args);

// Runs any program with `args` (argv[0] included), capturing output.
CommandResult RunProgram(const std::vector<std::string>& argv);

// The same with standard output sent to `stdout_path` (e.g. /dev/full, a
// file the test reads itself); `out` stays empty.
CommandResult RunProgramWithStdout(const std::vector<std::string>& argv,
                                   const std::string& stdout_path);

// The VmFlags line of this process's mapping that holds `address` (from
// /proc/self/smaps; " hg" marks huge-page advice), "" when none holds it.
std::string VmFlagsOf(const void* address);

std::string ReadFile(const std::string& path);

// A PNG signature and IHDR chunk of `width` x `height` and nothing after:
// enough for what reads only a PNG's header, not an image to decode.
std::string PngHeaderBytes(uint32_t width, uint32_t height);
void WriteFile(const std::string& path, const std::string& bytes);

// Path of a file in the checkout or in ../shared/data.
std::string SourcePath(const std::string& relative);
std::string SharedDataPath(const std::string& relative);
// True when ../shared/data is present (tests that need it skip otherwise).
bool HaveSharedData();

// The message of the error that `run` throws as E, "" when it throws none,
// and "unexpected error: ..." for any other exception.
template <typename E, typename F>
std::string ErrorOf(F run) {
  try {
    run();
  } catch (const E& error) {
    return error.what();
  } catch (const std::exception& other) {
    return std::string("unexpected error: ") + other.what();
  }
  return "";
}

// Number of lines in `text` that are not empty.
int CountLines(const std::string& text);

// How many times `needle` occurs in `text` (overlaps included).
int CountOccurrences(const std::string& text, const std::string& needle);

}  // namespace areagraph::testing
