#pragma once

#include <string>
#include <utility>
#include <vector>

namespace areagraph::testing {

// A point of SVG path data, absolute.
struct PathPoint {
  double x = 0, y = 0;
};

// The subpaths of path data as SvgPathWriter writes it (M, l with implicit
// repeats, z), as absolute points; for checking what the viewer would draw.
std::vector<std::vector<PathPoint>> ParseSvgPath(const std::string& path);

// Every segment of the path, each as (from, to).
std::vector<std::pair<PathPoint, PathPoint>> PathSegments(const std::string& path);

}  // namespace areagraph::testing
