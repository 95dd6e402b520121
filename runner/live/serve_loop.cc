#include "runner/live/serve_loop.h"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <string>

#include "common/error.h"

namespace areagraph {
namespace {

volatile std::sig_atomic_t stop_requested = 0;

void RequestStop(int) { stop_requested = 1; }

}  // namespace

void ServeLimits::Check() const {
  if (count < 0) throw OptionsError("--count must be 0 (no limit) or positive");
  if (!(timeout_s >= 0)) throw OptionsError("--timeout must be 0 (none) or positive");
}

bool ServeUntilDone(const ServeLimits& limits, const char* what, const std::function<int()>& served,
                    const std::function<void(int wait_ms)>& serve) {
  struct sigaction action = {};
  action.sa_handler = RequestStop;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);

  using Clock = std::chrono::steady_clock;
  const Clock::time_point deadline =
      Clock::now() +
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits.timeout_s));
  while (!stop_requested && (limits.count == 0 || served() < limits.count)) {
    int wait_ms = 200;
    if (limits.timeout_s > 0) {
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
      if (left.count() <= 0) break;
      wait_ms = static_cast<int>(std::min<int64_t>(wait_ms, left.count()));
    }
    serve(wait_ms);
  }
  if (limits.count > 0 && served() < limits.count && !stop_requested) {
    throw Error("--timeout reached after " + std::to_string(served()) + " of " +
                std::to_string(limits.count) + " " + what);
  }
  return stop_requested != 0;
}

}  // namespace areagraph
