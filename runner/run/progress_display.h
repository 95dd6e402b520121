#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace areagraph {

// Progress of a collection on stderr. On a terminal: one bar redrawn in
// place (maps done out of total, rate, time left). Otherwise: one plain line
// per finished map, which logs and CI output keep readable.
class ProgressDisplay {
 public:
  ProgressDisplay(int total, bool terminal, std::FILE* out = stderr);

  // A map has ended; `line` describes it (used when not on a terminal).
  void MapDone(bool failed, const std::string& line);
  // Redraws the bar if it is due (called often).
  void Tick();
  // Clears the bar before the summary.
  void Finish();

 private:
  void DrawBar();

  int total_;
  bool terminal_;
  std::FILE* out_;
  int done_ = 0;
  int failed_ = 0;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace areagraph
