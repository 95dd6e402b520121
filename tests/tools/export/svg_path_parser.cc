#include "tests/tools/export/svg_path_parser.h"

#include <cctype>
#include <cstdlib>
#include <stdexcept>

namespace areagraph::testing {

std::vector<std::vector<PathPoint>> ParseSvgPath(const std::string& path) {
  std::vector<std::vector<PathPoint>> subpaths;
  PathPoint current, start;
  char command = 0;
  std::vector<double> numbers;
  size_t i = 0;
  auto flush = [&] {
    if (numbers.size() % 2 != 0) throw std::runtime_error("odd number count in path");
    for (size_t n = 0; n < numbers.size(); n += 2) {
      if (command == 'M' && n == 0) {
        current = {numbers[0], numbers[1]};
        start = current;
        subpaths.push_back({current});
      } else if (command == 'l' || command == 'M') {
        // After M, further pairs are absolute lines; SvgPathWriter never writes them.
        if (command == 'M') throw std::runtime_error("implicit absolute line after M");
        current = {current.x + numbers[n], current.y + numbers[n + 1]};
        subpaths.back().push_back(current);
      } else {
        throw std::runtime_error(std::string("unexpected command ") + command);
      }
    }
    numbers.clear();
  };
  while (i < path.size()) {
    const char c = path[i];
    if (c == 'M' || c == 'l' || c == 'z') {
      flush();
      command = c;
      if (c == 'z') {
        subpaths.back().push_back(start);
        current = start;
      }
      ++i;
    } else if (c == ' ') {
      ++i;
    } else {
      char* end = nullptr;
      numbers.push_back(std::strtod(path.c_str() + i, &end));
      if (end == path.c_str() + i)
        throw std::runtime_error("bad number in path: " + path.substr(i));
      i = end - path.c_str();
    }
  }
  flush();
  return subpaths;
}

std::vector<std::pair<PathPoint, PathPoint>> PathSegments(const std::string& path) {
  std::vector<std::pair<PathPoint, PathPoint>> segments;
  for (const auto& subpath : ParseSvgPath(path)) {
    for (size_t i = 1; i < subpath.size(); ++i) segments.push_back({subpath[i - 1], subpath[i]});
  }
  return segments;
}

}  // namespace areagraph::testing
