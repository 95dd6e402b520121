#include "tools/render/canvas.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/geometry/ring_points.h"

namespace areagraph {
namespace {

// Canvas points carry kShift fractional bits (cv's fixed-point drawing).
constexpr int kShift = 4;
constexpr int kSubPixels = 1 << kShift;
// Lines, outlines and dots are not anti-aliased: a Voronoi diagram has tens
// of thousands of edges (anti-aliased, half of a render's instructions), and
// pictures of few colours are written with a palette. Labels still are.
constexpr int kLineType = cv::LINE_8;

// The whole canvas pixels that points with fractional bits can touch.
cv::Rect PixelBox(const std::vector<cv::Point>& points) {
  const cv::Rect fine = cv::boundingRect(points);
  const int x0 = fine.x >> kShift, y0 = fine.y >> kShift;  // floor, also below zero
  const int x1 = ((fine.x + fine.width) >> kShift) + 2, y1 = ((fine.y + fine.height) >> kShift) + 2;
  return cv::Rect(x0, y0, x1 - x0, y1 - y0);
}

// Draws each pair of points as a line into `target` with one cv::polylines
// call: each two-point contour is drawn as cv::line draws it (the same
// rounded ends for thick lines), one after the other.
void DrawSegments(cv::Mat& target, const Canvas& canvas,
                  const std::vector<std::pair<cv::Point2d, cv::Point2d>>& lines,
                  const cv::Scalar& colour, int thickness) {
  if (lines.empty()) return;
  std::vector<cv::Point> points;
  points.reserve(2 * lines.size());
  for (const auto& [a, b] : lines) {
    points.push_back(canvas.ToCanvas(a));
    points.push_back(canvas.ToCanvas(b));
  }
  std::vector<const cv::Point*> starts(lines.size());
  for (size_t i = 0; i < lines.size(); ++i) starts[i] = &points[2 * i];
  const std::vector<int> sizes(lines.size(), 2);
  cv::polylines(target, starts.data(), sizes.data(), static_cast<int>(lines.size()), false, colour,
                thickness, kLineType, kShift);
}

std::vector<cv::Point> CanvasRing(const Canvas& canvas, const proto::Ring& ring) {
  std::vector<cv::Point> points;
  points.reserve(RingSize(ring));
  for (int i = 0; i < RingSize(ring); ++i) {
    const Eigen::Vector2d point = RingPoint(ring, i);
    points.push_back(canvas.ToCanvas(cv::Point2d(point.x(), point.y())));
  }
  return points;
}

}  // namespace

Canvas::Canvas(const std::string& cells, int width, int height, int scale) : scale_(scale) {
  // The map's three states are greys (cv::LUT), upscaled on one byte per
  // pixel; grey to BGR once something is drawn. ag-render runs OpenCV on
  // one thread (cv::setNumThreads(0)), so these start no TBB workers there.
  cv::Mat grey_of(1, 256, CV_8UC1, cv::Scalar(kUnknownCellGrey));
  grey_of.at<uint8_t>(proto::CELL_FREE) = kFreeCellGrey;
  grey_of.at<uint8_t>(proto::CELL_OCCUPIED) = kOccupiedCellGrey;
  const size_t count = static_cast<size_t>(width) * height;
  std::string padded;  // missing cells are unknown
  if (cells.size() < count) {
    padded = cells;
    padded.resize(count, static_cast<char>(proto::CELL_UNKNOWN));
  }
  const std::string& states = cells.size() < count ? padded : cells;
  cv::Mat grey;
  cv::LUT(cv::Mat(height, width, CV_8UC1, const_cast<char*>(states.data())), grey_of, grey);
  grey_ = scale > 1 ? UpscaleNearest(grey, scale) : grey;
}

cv::Mat UpscaleNearest(const cv::Mat& grey, int scale) {
  // Source columns and rows as cv::resize's INTER_NEAREST computes them (the
  // floor of the index times the reciprocal scale), so that the picture
  // stays byte for byte the same; a row that repeats the one above is
  // copied, which makes this less than half of cv::resize's instructions
  // (lab_a at 3 x: 9.6 M against 22 M).
  const double inverse = 1.0 / scale;
  const auto source = [inverse](int index, int size) {
    return std::min(static_cast<int>(std::floor(index * inverse)), size - 1);
  };
  cv::Mat big(grey.rows * scale, grey.cols * scale, CV_8UC1);
  std::vector<int> source_col(big.cols);
  for (int x = 0; x < big.cols; ++x) source_col[x] = source(x, grey.cols);
  int previous_row = -1;
  for (int y = 0; y < big.rows; ++y) {
    const int row = source(y, grey.rows);
    uint8_t* out = big.ptr<uint8_t>(y);
    if (row == previous_row) {
      std::copy(big.ptr<uint8_t>(y - 1), big.ptr<uint8_t>(y - 1) + big.cols, out);
    } else {
      const uint8_t* in = grey.ptr<uint8_t>(row);
      for (int x = 0; x < big.cols; ++x) out[x] = in[source_col[x]];
    }
    previous_row = row;
  }
  return big;
}

cv::Mat& Canvas::image() {
  if (image_.empty()) {
    cv::cvtColor(grey_, image_, cv::COLOR_GRAY2BGR);
    grey_.release();
  }
  return image_;
}

cv::Point Canvas::ToCanvas(const proto::Point2& point) const {
  return ToCanvas(cv::Point2d(point.x(), point.y()));
}

cv::Point Canvas::ToCanvas(const cv::Point2d& point) const {
  // Sub-pixel precision through cv's fixed-point shift (4 bits).
  return cv::Point(static_cast<int>(std::lround(point.x * scale_ * 16)),
                   static_cast<int>(std::lround(point.y * scale_ * 16)));
}

void Canvas::Line(const proto::Point2& a, const proto::Point2& b, const cv::Scalar& colour,
                  int thickness) {
  Line(cv::Point2d(a.x(), a.y()), cv::Point2d(b.x(), b.y()), colour, thickness);
}

void Canvas::Line(const cv::Point2d& a, const cv::Point2d& b, const cv::Scalar& colour,
                  int thickness) {
  cv::line(image(), ToCanvas(a), ToCanvas(b), colour, thickness, kLineType, kShift);
}

void Canvas::Lines(const std::vector<std::pair<cv::Point2d, cv::Point2d>>& lines,
                   const cv::Scalar& colour, int thickness) {
  DrawSegments(image(), *this, lines, colour, thickness);
}

void Canvas::Dot(const proto::Point2& at, const cv::Scalar& colour, int radius) {
  cv::circle(image(), ToCanvas(at), radius * kSubPixels, colour, cv::FILLED, kLineType, kShift);
}

void Canvas::Outline(const proto::Ring& ring, const cv::Scalar& colour, int thickness) {
  if (RingSize(ring) < 2) return;
  const std::vector<std::vector<cv::Point>> rings = {CanvasRing(*this, ring)};
  cv::polylines(image(), rings, true, colour, thickness, kLineType, kShift);
}

void Canvas::Fill(const proto::Polygon& polygon, const cv::Scalar& colour, double alpha) {
  if (RingSize(polygon.outer()) < 3) return;
  std::vector<std::vector<cv::Point>> rings = {CanvasRing(*this, polygon.outer())};
  // Only the polygon's bounding box (holes lie inside it) is masked and
  // blended: a whole canvas per polygon made big maps take minutes.
  const cv::Rect box = PixelBox(rings[0]) & cv::Rect(0, 0, image().cols, image().rows);
  if (box.empty()) return;
  const cv::Point offset(-box.x * kSubPixels, -box.y * kSubPixels);
  cv::Mat mask = cv::Mat::zeros(box.size(), CV_8UC1);
  cv::fillPoly(mask, rings, cv::Scalar(255), cv::LINE_8, kShift, offset);
  for (const proto::Ring& hole : polygon.holes()) {
    rings = {CanvasRing(*this, hole)};
    cv::fillPoly(mask, rings, cv::Scalar(0), cv::LINE_8, kShift, offset);
  }
  cv::Mat area = image()(box), tinted;
  cv::addWeighted(area, 1.0 - alpha, cv::Mat(box.size(), image().type(), colour), alpha, 0, tinted);
  tinted.copyTo(area, mask);
}

void Canvas::FaintLines(const std::vector<std::pair<cv::Point2d, cv::Point2d>>& lines,
                        const cv::Scalar& colour, double alpha) {
  if (lines.empty()) return;
  cv::Mat& picture = image();
  cv::Mat mask = cv::Mat::zeros(picture.size(), CV_8UC1);
  DrawSegments(mask, *this, lines, cv::Scalar(255), 1);
  // Only the masked pixels, each through its channel's table: float maths
  // over the whole picture (cv::addWeighted) was most of this call.
  const BlendTables blend = BlendTablesFor(colour, alpha);
  for (int y = 0; y < picture.rows; ++y) {
    const uint8_t* in_mask = mask.ptr<uint8_t>(y);
    uint8_t* pixel = picture.ptr<uint8_t>(y);
    for (int x = 0; x < picture.cols; ++x, pixel += 3) {
      if (in_mask[x] == 0) continue;
      for (int c = 0; c < 3; ++c) pixel[c] = blend[c][pixel[c]];
    }
  }
}

BlendTables BlendTablesFor(const cv::Scalar& colour, double alpha) {
  // As cv::addWeighted(picture, 1 - alpha, colour, alpha, 0) computes each
  // 8-bit value: in float, rounded to the nearest (ties to even). With
  // alpha 0.5 every sum is exact, so no order of operations can differ.
  const auto weight = static_cast<float>(alpha), rest = static_cast<float>(1.0 - alpha);
  BlendTables tables;
  for (int c = 0; c < 3; ++c) {
    const float tint = static_cast<float>(cv::saturate_cast<uint8_t>(colour[c])) * weight;
    for (int v = 0; v < 256; ++v) {
      tables[c][v] = cv::saturate_cast<uint8_t>(static_cast<float>(v) * rest + tint);
    }
  }
  return tables;
}

void Canvas::Label(const proto::Point2& at, const std::string& text, const cv::Scalar& colour) {
  const double font_scale = std::clamp(0.25 * scale_, 0.4, 0.9);
  int baseline = 0;
  const cv::Size size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, font_scale, 1, &baseline);
  const cv::Point origin(static_cast<int>(at.x() * scale_) - size.width / 2,
                         static_cast<int>(at.y() * scale_) + size.height / 2);
  cv::putText(image(), text, origin, cv::FONT_HERSHEY_SIMPLEX, font_scale,
              cv::Scalar(255, 255, 255), 3, cv::LINE_AA);
  cv::putText(image(), text, origin, cv::FONT_HERSHEY_SIMPLEX, font_scale, colour, 1, cv::LINE_AA);
}

void Canvas::PaintCells(const google::protobuf::RepeatedField<int32_t>& cells, int width,
                        const cv::Scalar& colour) {
  // The pixel blocks are written directly: per cell, cv::rectangle's set-up
  // costs more than its pixels (lab_a's clean picture: 74 -> 64 M instructions).
  cv::Mat& picture = image();
  const cv::Vec3b bgr(cv::saturate_cast<uint8_t>(colour[0]), cv::saturate_cast<uint8_t>(colour[1]),
                      cv::saturate_cast<uint8_t>(colour[2]));
  for (const int32_t cell : cells) {
    if (cell < 0 || width <= 0) continue;
    // Clipped to the picture, as cv::rectangle clips.
    const int64_t x0 = int64_t{cell % width} * scale_, y0 = int64_t{cell / width} * scale_;
    if (x0 >= picture.cols || y0 >= picture.rows) continue;
    const int x1 = static_cast<int>(std::min<int64_t>(x0 + scale_, picture.cols));
    const int y1 = static_cast<int>(std::min<int64_t>(y0 + scale_, picture.rows));
    for (int y = static_cast<int>(y0); y < y1; ++y) {
      cv::Vec3b* row = picture.ptr<cv::Vec3b>(y);
      for (int x = static_cast<int>(x0); x < x1; ++x) row[x] = bgr;
    }
  }
}

cv::Scalar DistinctColour(int id) {
  // Golden-angle hue steps keep neighbouring ids apart; HSV -> BGR by hand.
  const double hue = std::fmod(id * 137.508, 360.0) / 60.0;
  const double saturation = id % 2 == 0 ? 0.65 : 0.85, value = id % 3 == 0 ? 0.95 : 0.8;
  const double c = value * saturation, x = c * (1 - std::fabs(std::fmod(hue, 2.0) - 1));
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(hue)) {
    case 0:
      r = c, g = x;
      break;
    case 1:
      r = x, g = c;
      break;
    case 2:
      g = c, b = x;
      break;
    case 3:
      g = x, b = c;
      break;
    case 4:
      r = x, b = c;
      break;
    default:
      r = c, b = x;
      break;
  }
  const double m = value - c;
  return cv::Scalar((b + m) * 255, (g + m) * 255, (r + m) * 255);
}

int DefaultScale(int width, int height) {
  const int longer = std::max(1, std::max(width, height));
  return std::clamp(1000 / longer, 1, 8);
}

}  // namespace areagraph
