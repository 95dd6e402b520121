#include "tools/export/svg_path.h"

#include <cmath>

#include "stages/geometry/ring_points.h"

namespace areagraph {
namespace {

int64_t ToTenths(double value) { return static_cast<int64_t>(std::llround(value * 10)); }

}  // namespace

std::string TenthsText(int64_t tenths) {
  std::string text = tenths < 0 ? "-" : "";
  const uint64_t magnitude = tenths < 0 ? -static_cast<uint64_t>(tenths) : tenths;
  if (magnitude >= 10) text += std::to_string(magnitude / 10);
  if (magnitude % 10 != 0) {
    text += '.';
    text += static_cast<char>('0' + magnitude % 10);
  } else if (magnitude < 10) {
    return "0";
  }
  return text;
}

void SvgPathWriter::AppendNumber(int64_t tenths) {
  const std::string number = TenthsText(tenths);
  const char last = text_.empty() ? ' ' : text_.back();
  const bool after_letter = last == 'M' || last == 'l';
  if (!after_letter && number[0] != '-') text_ += ' ';
  text_ += number;
}

void SvgPathWriter::MoveTo(double x, double y) {
  x_ = ToTenths(x);
  y_ = ToTenths(y);
  text_ += 'M';
  AppendNumber(x_);
  AppendNumber(y_);
  started_ = true;
  in_lines_ = false;
}

void SvgPathWriter::LineTo(double x, double y) {
  if (!started_) return;
  const int64_t to_x = ToTenths(x), to_y = ToTenths(y);
  if (to_x == x_ && to_y == y_) return;
  if (!in_lines_) text_ += 'l';
  in_lines_ = true;
  AppendNumber(to_x - x_);
  AppendNumber(to_y - y_);
  x_ = to_x;
  y_ = to_y;
}

void SvgPathWriter::Close() {
  if (!started_) return;
  text_ += 'z';
  // After z the current point is the subpath's start, which is not tracked:
  // the next subpath must begin with MoveTo.
  started_ = false;
  in_lines_ = false;
}

void SvgPathWriter::ContinueAt(double x, double y) {
  if (started_ && ToTenths(x) == x_ && ToTenths(y) == y_) return;
  MoveTo(x, y);
}

namespace {

// A closed subpath; rings of fewer than 3 points draw nothing.
void AppendRing(const proto::Ring& ring, SvgPathWriter& path) {
  const int n = RingSize(ring);
  if (n < 3) return;
  path.MoveTo(RingPoint(ring, 0).x(), RingPoint(ring, 0).y());
  for (int i = 1; i < n; ++i) path.LineTo(RingPoint(ring, i).x(), RingPoint(ring, i).y());
  path.Close();
}

}  // namespace

std::string RingPath(const proto::Ring& ring) {
  SvgPathWriter path;
  AppendRing(ring, path);
  return path.text();
}

std::string PolygonPath(const proto::Polygon& polygon) {
  SvgPathWriter path;
  AppendRing(polygon.outer(), path);
  for (const proto::Ring& hole : polygon.holes()) AppendRing(hole, path);
  return path.text();
}

std::string PolylinePath(const google::protobuf::RepeatedPtrField<proto::Point2>& points) {
  SvgPathWriter path;
  if (points.empty()) return "";
  path.MoveTo(points[0].x(), points[0].y());
  for (int i = 1; i < points.size(); ++i) path.LineTo(points[i].x(), points[i].y());
  return path.text();
}

double Rounded(double value, int decimals) {
  const double scale = std::pow(10.0, decimals);
  return std::round(value * scale) / scale;
}

}  // namespace areagraph
