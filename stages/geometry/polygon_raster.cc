#include "stages/geometry/polygon_raster.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "stages/geometry/parallel_ranges.h"
#include "stages/geometry/parallel_zeros.h"
#include "stages/geometry/ring_points.h"

namespace areagraph {
namespace {

// Sub-pixel bits for cv::fillPoly; OpenCV's pixel (c, r) is our point
// (c + .5, r + .5), hence the half-pixel shift.
constexpr int kShiftBits = 4;
constexpr double kScale = 1 << kShiftBits;

std::vector<cv::Point> ToCv(const proto::Ring& ring) {
  std::vector<cv::Point> points;
  const int n = RingSize(ring);
  points.reserve(n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d p = RingPoint(ring, i);
    // Clamp absurd coordinates so the fixed-point values stay in int range.
    const double x = std::clamp(p.x(), -1e6, 1e6), y = std::clamp(p.y(), -1e6, 1e6);
    points.emplace_back(static_cast<int>(std::lround((x - 0.5) * kScale)),
                        static_cast<int>(std::lround((y - 0.5) * kScale)));
  }
  return points;
}

// The outline and holes (of at least 3 points) of a polygon as cv::fillPoly
// takes them; none when the outline has fewer than 3 points.
std::vector<std::vector<cv::Point>> Contours(const proto::Polygon& polygon) {
  if (RingSize(polygon.outer()) < 3) return {};
  std::vector<std::vector<cv::Point>> contours{ToCv(polygon.outer())};
  for (const proto::Ring& hole : polygon.holes()) {
    if (RingSize(hole) >= 3) contours.push_back(ToCv(hole));
  }
  return contours;
}

// Cells beyond the contours' extreme points that cv::fillPoly may still
// paint (its outlines round to the nearest cell): a box this much larger
// holds all it paints.
constexpr int kBoxMargin = 2;

// The cells of `size` that painting `contours` can reach.
cv::Rect PaintedBox(const std::vector<std::vector<cv::Point>>& contours, cv::Size size) {
  int x0 = contours[0][0].x, x1 = x0, y0 = contours[0][0].y, y1 = y0;
  for (const auto& contour : contours) {
    for (const cv::Point& p : contour) {
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
      y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
  }
  const cv::Point tl((x0 >> kShiftBits) - kBoxMargin, (y0 >> kShiftBits) - kBoxMargin);
  const cv::Point br((x1 >> kShiftBits) + kBoxMargin + 1, (y1 >> kShiftBits) + kBoxMargin + 1);
  return cv::Rect(tl, br) & cv::Rect(cv::Point(0, 0), size);
}

// One polygon painted into its own box.
struct BoxedPolygon {
  std::vector<std::vector<cv::Point>> contours;
  cv::Rect box;
  int value = 0;
  size_t offset = 0;  // of its mask in the chunk's buffer
};

// At most about this many box cells are painted before they are joined (the
// masks' memory), and at least this many per parallel range of rows.
constexpr size_t kChunkCells = size_t(1) << 22;
constexpr size_t kMinRangeCells = size_t(1) << 16;
// At least this many polygons per parallel range of painting.
constexpr size_t kMinRangePolygons = 8;

// row[c] = value where mask[c] is 1 (fillPoly's value in the masks), eight
// cells at a time across a box's empty and full stretches.
void PaintRow(const uint8_t* mask, int* row, int n, int value) {
  constexpr uint64_t kFull = 0x0101010101010101ull;
  int c = 0;
  for (; c + 8 <= n; c += 8) {
    uint64_t eight;
    std::memcpy(&eight, mask + c, sizeof(eight));
    if (eight == 0) continue;
    if (eight == kFull) {
      for (int i = 0; i < 8; ++i) row[c + i] = value;
      continue;
    }
    for (int i = 0; i < 8; ++i) {
      if (mask[c + i] != 0) row[c + i] = value;
    }
  }
  for (; c < n; ++c) {
    if (mask[c] != 0) row[c] = value;
  }
}

// Paints `chunk` into `buffer` (their masks) and joins them into `labels`.
void PaintChunk(std::vector<BoxedPolygon>& chunk, std::vector<uint8_t>& buffer, cv::Mat* labels) {
  size_t cells = 0;
  for (BoxedPolygon& polygon : chunk) {
    polygon.offset = cells;
    cells += size_t(polygon.box.area());
  }
  buffer.assign(cells, 0);
  ForEachRange(chunk.size(), ParallelRangeCount(chunk.size(), kMinRangePolygons),
               [&](size_t begin, size_t end, int) {
                 for (size_t i = begin; i < end; ++i) {
                   BoxedPolygon& polygon = chunk[i];
                   // Whole cells: the same painting, moved.
                   const cv::Point shift(polygon.box.x << kShiftBits, polygon.box.y << kShiftBits);
                   for (auto& contour : polygon.contours) {
                     for (cv::Point& p : contour) p -= shift;
                   }
                   cv::Mat mask(polygon.box.size(), CV_8U, buffer.data() + polygon.offset);
                   cv::fillPoly(mask, polygon.contours, cv::Scalar(1), cv::LINE_8, kShiftBits);
                 }
               });
  // In order within each range of rows: later polygons over earlier ones.
  const int rows = labels->rows;
  const size_t min_rows = std::max<size_t>(8, kMinRangeCells / std::max(labels->cols, 1));
  ForEachRange(size_t(rows), ParallelRangeCount(size_t(rows), min_rows),
               [&](size_t begin, size_t end, int) {
                 for (const BoxedPolygon& polygon : chunk) {
                   const cv::Rect& box = polygon.box;
                   const int r0 = std::max<int>(box.y, int(begin));
                   const int r1 = std::min<int>(box.y + box.height, int(end));
                   for (int r = r0; r < r1; ++r) {
                     PaintRow(buffer.data() + polygon.offset + size_t(r - box.y) * box.width,
                              labels->ptr<int>(r) + box.x, box.width, polygon.value);
                   }
                 }
               });
}

}  // namespace

cv::Mat PolygonLabels(const std::vector<std::pair<const proto::Polygon*, int>>& polygons,
                      cv::Size size) {
  cv::Mat labels = ZerosInParallel(size, CV_32S);
  std::vector<BoxedPolygon> chunk;
  std::vector<uint8_t> buffer;
  size_t cells = 0;
  for (const auto& [polygon, value] : polygons) {
    BoxedPolygon boxed;
    boxed.contours = Contours(*polygon);
    if (boxed.contours.empty()) continue;
    boxed.box = PaintedBox(boxed.contours, size);
    if (boxed.box.empty()) continue;
    boxed.value = value;
    if (size_t(boxed.box.area()) >= kChunkCells) {
      // Too big a mask: painted in place, after what came before.
      if (!chunk.empty()) PaintChunk(chunk, buffer, &labels);
      chunk.clear();
      cells = 0;
      cv::fillPoly(labels, boxed.contours, cv::Scalar(value), cv::LINE_8, kShiftBits);
      continue;
    }
    cells += size_t(boxed.box.area());
    chunk.push_back(std::move(boxed));
    if (cells >= kChunkCells) {
      PaintChunk(chunk, buffer, &labels);
      chunk.clear();
      cells = 0;
    }
  }
  if (!chunk.empty()) PaintChunk(chunk, buffer, &labels);
  return labels;
}

void FillPolygon(const proto::Polygon& polygon, int value, cv::Mat* image) {
  const std::vector<std::vector<cv::Point>> contours = Contours(polygon);
  if (contours.empty()) return;
  cv::fillPoly(*image, contours, cv::Scalar(value), cv::LINE_8, kShiftBits);
}

cv::Mat PolygonMask(const proto::Polygon& polygon, cv::Size size) {
  cv::Mat mask = cv::Mat::zeros(size, CV_8U);
  FillPolygon(polygon, 255, &mask);
  return mask;
}

cv::Mat BoundaryMask(const google::protobuf::RepeatedPtrField<proto::Polygon>& parts,
                     const proto::Polygon& boundary, cv::Size size) {
  if (parts.empty()) return PolygonMask(boundary, size);
  cv::Mat mask = cv::Mat::zeros(size, CV_8U);
  for (const proto::Polygon& part : parts) FillPolygon(part, 255, &mask);
  return mask;
}

}  // namespace areagraph
