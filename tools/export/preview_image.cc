#include "tools/export/preview_image.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "stages/common/map_frame.h"
#include "tools/export/area_label_image.h"
#include "tools/export/area_polygons.h"
#include "tools/export/export_ids.h"

namespace areagraph {

namespace {

constexpr int kMinLongSidePx = 800;
constexpr int kMaxScale = 8;

// Saturation per kind on OpenCV's 0..255 scale, and value.
cv::Vec3b AreaColour(const proto::Area& area) {
  const int hue = static_cast<int>(std::fmod(area.id() * 137.508, 360.0) / 2);  // 0..179
  const int saturation = area.kind() == proto::AREA_CORRIDOR ? 60 : 150;
  const int value = area.kind() == proto::AREA_DEAD_END ? 150 : 240;
  cv::Mat hsv(1, 1, CV_8UC3, cv::Scalar(hue, saturation, value)), bgr;
  cv::cvtColor(hsv, bgr, cv::COLOR_HSV2BGR);
  return bgr.at<cv::Vec3b>(0, 0);
}

// Pixel coordinates scaled, in OpenCV's fixed point with 4 fractional bits.
constexpr int kShift = 4;
cv::Point Scaled(double x_px, double y_px, int scale) {
  return {static_cast<int>(std::lround(x_px * scale * (1 << kShift))),
          static_cast<int>(std::lround(y_px * scale * (1 << kShift)))};
}

}  // namespace

cv::Mat AreaGraphPreview(const proto::AreaGraph& graph) {
  const cv::Mat labels = AreaLabelImage(graph);
  const ExportIds ids(graph);
  const int long_side = std::max(1, std::max(labels.cols, labels.rows));
  const int scale = std::clamp((kMinLongSidePx + long_side - 1) / long_side, 1, kMaxScale);
  std::vector<cv::Vec3b> colours(graph.areas_size());
  cv::Mat small(labels.size(), CV_8UC3, cv::Scalar(255, 255, 255));
  std::vector<int> index_of_label(65536, -1);
  for (int i = 0; i < graph.areas_size(); ++i) {
    colours[i] = AreaColour(graph.areas(i));
    index_of_label[ids.Of(graph.areas(i)) + 1] = i;
  }
  for (int r = 0; r < labels.rows; ++r) {
    for (int c = 0; c < labels.cols; ++c) {
      const int index = index_of_label[labels.at<uint16_t>(r, c)];
      if (index >= 0) small.at<cv::Vec3b>(r, c) = colours[index];
    }
  }
  cv::Mat preview;
  cv::resize(small, preview, cv::Size(), scale, scale, cv::INTER_NEAREST);
  for (const proto::Area& area : graph.areas()) {
    const proto::Polygon polygon = AreaPolygonPixels(graph, area);
    std::vector<cv::Point> ring;
    for (const proto::Point2& p : polygon.outer().points()) {
      ring.push_back(Scaled(p.x(), p.y(), scale));
    }
    cv::polylines(preview, std::vector<std::vector<cv::Point>>{ring}, true, cv::Scalar(90, 90, 90),
                  1, cv::LINE_AA, kShift);
  }
  const MapTransform transform(graph.frame());
  for (const proto::Passage& passage : graph.passages()) {
    std::vector<cv::Point> points;
    for (const proto::Point2& p : PassageLine(passage)) {
      const Eigen::Vector2d pixel = transform.WorldToPixel({p.x(), p.y()});
      points.push_back(Scaled(pixel.x(), pixel.y(), scale));
    }
    cv::polylines(preview, std::vector<std::vector<cv::Point>>{points}, false,
                  cv::Scalar(0, 0, 220), std::max(2, scale / 2), cv::LINE_AA, kShift);
  }
  return preview;
}

}  // namespace areagraph
