#include "common/stderr_capture.h"

#include <unistd.h>

#include <iostream>

namespace areagraph {

ScopedStderrCapture::ScopedStderrCapture() {
  std::cerr.flush();
  std::fflush(stderr);
  capture_ = std::tmpfile();
  if (capture_ == nullptr) return;
  saved_fd_ = dup(STDERR_FILENO);
  if (saved_fd_ < 0 || dup2(fileno(capture_), STDERR_FILENO) < 0) {
    // Capturing is a nicety: without it the decoder's noise just stays visible.
    if (saved_fd_ >= 0) close(saved_fd_);
    saved_fd_ = -1;
    std::fclose(capture_);
    capture_ = nullptr;
  }
}

ScopedStderrCapture::~ScopedStderrCapture() {
  if (capture_ == nullptr) return;
  std::cerr.flush();
  std::fflush(stderr);
  dup2(saved_fd_, STDERR_FILENO);
  close(saved_fd_);
  std::fclose(capture_);
}

std::string ScopedStderrCapture::Text() {
  if (capture_ == nullptr) return {};
  std::cerr.flush();
  std::fflush(stderr);
  std::string text;
  std::rewind(capture_);
  char buffer[4096];
  size_t read = 0;
  while ((read = std::fread(buffer, 1, sizeof(buffer), capture_)) > 0) text.append(buffer, read);
  std::fseek(capture_, 0, SEEK_END);
  return text;
}

}  // namespace areagraph
