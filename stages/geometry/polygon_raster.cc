#include "stages/geometry/polygon_raster.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace areagraph {
namespace {

// Sub-pixel bits for cv::fillPoly; OpenCV's pixel (c, r) is our point
// (c + .5, r + .5), hence the half-pixel shift.
constexpr int kShiftBits = 4;
constexpr double kScale = 1 << kShiftBits;

std::vector<cv::Point> ToCv(const proto::Ring& ring) {
  std::vector<cv::Point> points;
  points.reserve(ring.points_size());
  for (const proto::Point2& p : ring.points()) {
    // Clamp absurd coordinates so the fixed-point values stay in int range.
    const double x = std::clamp(p.x(), -1e6, 1e6), y = std::clamp(p.y(), -1e6, 1e6);
    points.emplace_back(static_cast<int>(std::lround((x - 0.5) * kScale)),
                        static_cast<int>(std::lround((y - 0.5) * kScale)));
  }
  return points;
}

}  // namespace

void FillPolygon(const proto::Polygon& polygon, int value, cv::Mat* image) {
  if (polygon.outer().points_size() < 3) return;
  std::vector<std::vector<cv::Point>> contours{ToCv(polygon.outer())};
  for (const proto::Ring& hole : polygon.holes()) {
    if (hole.points_size() >= 3) contours.push_back(ToCv(hole));
  }
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
