#include "stages/merge/path_cells.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <opencv2/imgproc.hpp>

namespace areagraph {

void PaintPathCells(const PointList& path, int value, cv::Mat* labels, cv::Mat* marks) {
  CV_Assert(labels->type() == CV_32S && marks->type() == CV_8U && labels->size() == marks->size());
  CV_Assert(labels->isContinuous() && marks->isContinuous());
  const int cols = labels->cols, rows = labels->rows;
  int* label = labels->ptr<int>();
  uint8_t* mark = marks->ptr<uint8_t>();
  auto paint = [&](int64_t index) {
    label[index] = value;
    mark[index] = 1;
  };
  auto inside = [&](const cv::Point& p) {
    return p.x >= 0 && p.y >= 0 && p.x < cols && p.y < rows;
  };
  // cv::polylines draws nothing for a single point.
  if (path.size() < 2) return;
  auto cell = [](const Eigen::Vector2d& p) {
    return cv::Point(static_cast<int>(std::floor(p.x())), static_cast<int>(std::floor(p.y())));
  };
  cv::Point from = cell(path[0]);
  for (size_t i = 1; i < path.size(); ++i) {
    const cv::Point to = cell(path[i]);
    if ((from.x == to.x || from.y == to.y) && inside(from) && inside(to)) {
      // Along a row or a column: every cell between the ends.
      const int64_t step =
          from.x == to.x ? (to.y > from.y ? cols : -cols) : (to.x > from.x ? 1 : -1);
      const int64_t last = static_cast<int64_t>(to.y) * cols + to.x;
      for (int64_t at = static_cast<int64_t>(from.y) * cols + from.x;; at += step) {
        paint(at);
        if (at == last) break;
      }
    } else {
      cv::LineIterator line(*labels, from, to, 4, /*leftToRight=*/true);
      for (int k = 0; k < line.count; ++k, ++line) {
        paint(reinterpret_cast<int*>(*line) - label);
      }
    }
    from = to;
  }
}

}  // namespace areagraph
