#pragma once

#include <functional>

namespace areagraph {

// Longest accepted --timeout (about 115 days); longer ones overflow the clock.
inline constexpr double kMaxTimeoutS = 1e7;

// How long a live tool serves: up to `count` items (0: no limit) and up to
// `timeout_s` seconds (0: no limit). Check throws OptionsError for negative
// values and a timeout that is not finite or beyond kMaxTimeoutS.
struct ServeLimits {
  int count = 0;
  double timeout_s = 0;
  void Check() const;
};

// Calls `serve(wait_ms)` (which handles what arrives within wait_ms) until
// `served()` reaches the count, the timeout passes, or SIGINT/SIGTERM
// arrives (the handlers are installed here; the item in hand is finished).
// Returns true when a signal stopped it. Throws Error naming `what` when
// the timeout passed before the count was reached.
bool ServeUntilDone(const ServeLimits& limits, const char* what, const std::function<int()>& served,
                    const std::function<void(int wait_ms)>& serve);

}  // namespace areagraph
