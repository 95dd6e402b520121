#pragma once

#include <cstdio>
#include <string>

namespace areagraph {

// Redirects file descriptor 2 into a temporary file while alive. libpng and
// OpenCV's decoders print to stderr on bad files; capturing that keeps a
// failed import down to the one error line that the caller prints. Not for
// concurrent use with other threads that write to stderr: their output would
// be captured too.
class ScopedStderrCapture {
 public:
  ScopedStderrCapture();
  ~ScopedStderrCapture();
  ScopedStderrCapture(const ScopedStderrCapture&) = delete;
  ScopedStderrCapture& operator=(const ScopedStderrCapture&) = delete;

  // Everything written to stderr so far.
  std::string Text();

 private:
  int saved_fd_ = -1;
  std::FILE* capture_ = nullptr;
};

}  // namespace areagraph
