#include "common/text.h"

#include <sstream>

namespace areagraph {

std::string FormatNumber(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string ShortKey(const std::string& cache_key) { return cache_key.substr(0, 12); }

std::string OneLine(const std::string& text) {
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  std::string line;
  bool pending_break = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n' || c == '\r') {
      pending_break = true;
      while (!line.empty() && blank(line.back())) line.pop_back();
      continue;
    }
    if (pending_break && blank(c)) continue;
    if (pending_break && !line.empty()) line += "; ";
    pending_break = false;
    if (c == '\t') {
      line += ' ';
    } else if (!(line.empty() && c == ' ')) {
      line += c;
    }
  }
  while (!line.empty() && blank(line.back())) line.pop_back();
  return line;
}

}  // namespace areagraph
