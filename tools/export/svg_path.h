#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "proto/geometry.pb.h"

namespace areagraph {

// SVG path data in map pixels, kept short for pages that draw whole maps:
// coordinates are rounded to a tenth of a pixel (invisible even when one cell
// fills the screen), every point after a subpath's first is relative to the
// one before, numbers drop leading zeros, and segments that round to nothing
// are left out.
class SvgPathWriter {
 public:
  // Starts a subpath at (x, y).
  void MoveTo(double x, double y);
  // A line from the current point; ignored before any MoveTo.
  void LineTo(double x, double y);
  // Closes the current subpath.
  void Close();
  // Starts a subpath at (x, y) unless the current point already is (x, y):
  // for chaining segments that meet end to end.
  void ContinueAt(double x, double y);

  const std::string& text() const { return text_; }
  bool empty() const { return text_.empty(); }

 private:
  void AppendNumber(int64_t tenths);

  std::string text_;
  bool started_ = false;
  bool in_lines_ = false;  // after an 'l', further pairs need no letter
  int64_t x_ = 0, y_ = 0;  // current point, in tenths of a pixel
};

// Tenths of a pixel as the shortest decimal text: 125 -> "12.5", 5 -> ".5",
// -20 -> "-2".
std::string TenthsText(int64_t tenths);

// A closed ring, a polygon with its holes (even-odd or non-zero fill both
// work: holes run as stored), and an open polyline, as path data.
std::string RingPath(const proto::Ring& ring);
std::string PolygonPath(const proto::Polygon& polygon);
std::string PolylinePath(const google::protobuf::RepeatedPtrField<proto::Point2>& points);

// A value rounded to `decimals` places, for numbers the page prints.
double Rounded(double value, int decimals);

}  // namespace areagraph
