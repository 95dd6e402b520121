#include "tools/export/area_label_image.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/error.h"
#include "tools/export/area_polygons.h"
#include "tools/export/export_ids.h"

namespace areagraph {

// cv::fillPoly is not used on purpose: it also fills every pixel that the
// outline touches, so a 10x10 px square would cover 11x11 pixels and
// neighbouring areas would overlap by a pixel.
void FillPolygonByPixelCentres(const proto::Polygon& polygon, uint16_t value, cv::Mat* image) {
  std::vector<const proto::Ring*> rings = {&polygon.outer()};
  for (const proto::Ring& hole : polygon.holes()) rings.push_back(&hole);
  double top = INFINITY, bottom = -INFINITY;
  for (const proto::Ring* ring : rings) {
    for (const proto::Point2& point : ring->points()) {
      top = std::min(top, point.y());
      bottom = std::max(bottom, point.y());
    }
  }
  if (!(top <= bottom)) return;
  const int first_row = std::max(0, static_cast<int>(std::floor(top - 0.5)));
  const int last_row = std::min(image->rows - 1, static_cast<int>(std::ceil(bottom - 0.5)));
  std::vector<double> crossings;
  for (int row = first_row; row <= last_row; ++row) {
    const double y = row + 0.5;
    crossings.clear();
    for (const proto::Ring* ring : rings) {
      const int n = ring->points_size();
      for (int i = 0; i < n; ++i) {
        const proto::Point2& a = ring->points(i);
        const proto::Point2& b = ring->points((i + 1) % n);
        // Half-open in y, so a vertex on the scan line is crossed once.
        if ((a.y() <= y) == (b.y() <= y)) continue;
        crossings.push_back(a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
      }
    }
    std::sort(crossings.begin(), crossings.end());
    uint16_t* pixels = image->ptr<uint16_t>(row);
    for (size_t i = 0; i + 1 < crossings.size(); i += 2) {
      // Columns whose centre c + .5 lies in [left, right).
      const int begin = std::max(0, static_cast<int>(std::ceil(crossings[i] - 0.5)));
      const int end = std::min(image->cols, static_cast<int>(std::ceil(crossings[i + 1] - 0.5)));
      for (int column = begin; column < end; ++column) pixels[column] = value;
    }
  }
}

cv::Mat AreaLabelImage(const proto::AreaGraph& graph) {
  const int width = graph.frame().width_px(), height = graph.frame().height_px();
  if (width <= 0 || height <= 0) {
    throw InputError("the Area Graph's frame has no image size; cannot draw a label image");
  }
  const ExportIds ids(graph);
  cv::Mat labels(height, width, CV_16U, cv::Scalar(0));
  for (const proto::Area& area : graph.areas()) {
    const int32_t id = ids.Of(area);
    if (id < 0 || id > 65534) {
      throw InputError("area id " + std::to_string(id) +
                       " does not fit a 16-bit label image (label = id + 1)");
    }
    const proto::Polygon polygon = AreaPolygonPixels(graph, area);
    RequireFiniteVertices(polygon, AreaName(id));
    FillPolygonByPixelCentres(polygon, static_cast<uint16_t>(id + 1), &labels);
  }
  return labels;
}

}  // namespace areagraph
