#pragma once

#include <csignal>

namespace areagraph {

// SIGINT and SIGTERM, caught while it lives: the signal's number is kept
// (signal()) instead of ending the process, so that a runner can stop its
// workers, fold the store's log and say what happened. The handlers before
// it come back when it ends.
class Interruption {
 public:
  Interruption();
  ~Interruption();
  Interruption(const Interruption&) = delete;
  Interruption& operator=(const Interruption&) = delete;

  // 0 until a signal came, then its number. Written by the handler.
  static const volatile std::sig_atomic_t& signal();
  // "SIGINT" or "SIGTERM".
  static const char* SignalName(int signal);

 private:
  struct sigaction previous_int_ {};
  struct sigaction previous_term_ {};
};

}  // namespace areagraph
