#pragma once

#include <string>

namespace areagraph {

// `value` as the shortest text that a user would type: 0.05, 1.25, 1e+308,
// nan. For numbers in messages.
std::string FormatNumber(double value);

// `text` on one line: each run of line breaks (and the blanks around them)
// becomes "; ", and leading and trailing blanks go. Library messages (an
// OpenCV exception, SQLite's integrity findings, LCM's complaints) span
// lines; every error the tools print is one.
std::string OneLine(const std::string& text);

// The first 12 hex digits of a cache key: how keys are shown to users.
std::string ShortKey(const std::string& cache_key);

}  // namespace areagraph
