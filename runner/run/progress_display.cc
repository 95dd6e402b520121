#include "runner/run/progress_display.h"

namespace areagraph {
namespace {

std::string Clock(double seconds) {
  const long total = static_cast<long>(seconds + 0.5);
  char text[32];
  if (total >= 3600) {
    std::snprintf(text, sizeof(text), "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
  } else {
    std::snprintf(text, sizeof(text), "%ld:%02ld", total / 60, total % 60);
  }
  return text;
}

}  // namespace

ProgressDisplay::ProgressDisplay(int total, bool terminal, std::FILE* out)
    : total_(total),
      terminal_(terminal),
      out_(out),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

void ProgressDisplay::MapDone(bool failed, const std::string& line) {
  ++done_;
  failed_ += failed ? 1 : 0;
  if (terminal_) {
    Tick();
  } else {
    std::fprintf(out_, "ag-run: [%d/%d] %s\n", done_, total_, line.c_str());
    std::fflush(out_);
  }
}

void ProgressDisplay::Tick() {
  if (!terminal_) return;
  const auto now = std::chrono::steady_clock::now();
  if (done_ < total_ && now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  DrawBar();
}

void ProgressDisplay::DrawBar() {
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double rate = elapsed > 0 ? done_ / elapsed : 0;
  constexpr int kWidth = 30;
  const int filled = total_ > 0 ? done_ * kWidth / total_ : kWidth;
  std::string bar(static_cast<size_t>(filled), '#');
  bar.resize(kWidth, '.');
  std::string left = "--:--";
  if (rate > 0) left = Clock((total_ - done_) / rate);
  std::fprintf(out_, "\r\033[K[%s] %d/%d maps  %.1f maps/s  %s left", bar.c_str(), done_, total_,
               rate, left.c_str());
  if (failed_ > 0) std::fprintf(out_, "  %d failed", failed_);
  std::fflush(out_);
}

void ProgressDisplay::Finish() {
  if (!terminal_) return;
  DrawBar();
  std::fprintf(out_, "\n");
  std::fflush(out_);
}

}  // namespace areagraph
