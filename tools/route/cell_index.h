#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

namespace areagraph {

// Items with bounding boxes on a grid of square cells, to find those near a
// point, in a box or along a segment. A visit may see an item more than once.
class CellIndex {
 public:
  CellIndex() = default;
  // Item i covers boxes[i] (none when empty); `padding` widens every box
  // (and every query).
  CellIndex(const std::vector<Eigen::AlignedBox2d>& boxes, double cell_size, double padding);

  // Calls visit(item) for the items whose cells hold `point`.
  template <typename Visit>
  void ForEachAt(const Eigen::Vector2d& point, Visit visit) const {
    const int column = Column(point.x()), row = Row(point.y());
    if (column < 0 || column >= columns_ || row < 0 || row >= rows_) return;
    VisitCell(row * columns_ + column, visit);
  }

  // Calls visit(item) for the items whose cells overlap `box`.
  template <typename Visit>
  void ForEachInBox(const Eigen::AlignedBox2d& box, Visit visit) const {
    if (columns_ == 0) return;
    ForEachCellInBox(box, [&](int cell) { VisitCell(cell, visit); });
  }

  // Calls visit(item) for the items whose cells the segment passes, row by
  // row from a's end (a blocked segment is mostly blocked near where it
  // starts); stops as soon as a visit returns false, and returns false then.
  template <typename Visit>
  bool ForEachAlong(const Eigen::Vector2d& a, const Eigen::Vector2d& b, Visit visit) const {
    if (columns_ == 0) return true;
    const double low_y = std::min(a.y(), b.y()) - padding_;
    const double high_y = std::max(a.y(), b.y()) + padding_;
    const int first_row = ClampRow(Row(low_y)), last_row = ClampRow(Row(high_y));
    const double dy = b.y() - a.y();
    const bool rows_up = dy >= 0, columns_up = b.x() >= a.x();
    for (int step = 0; step <= last_row - first_row; ++step) {
      const int row = rows_up ? first_row + step : last_row - step;
      // The part of the segment within this row (widened by the padding).
      const double row_low = std::max(low_y, origin_.y() + row * cell_size_) - padding_;
      const double row_high = std::min(high_y, origin_.y() + (row + 1) * cell_size_) + padding_;
      double x0 = std::min(a.x(), b.x()), x1 = std::max(a.x(), b.x());
      if (std::abs(dy) > 1e-12) {
        const double t0 = std::clamp((row_low - a.y()) / dy, 0.0, 1.0);
        const double t1 = std::clamp((row_high - a.y()) / dy, 0.0, 1.0);
        const double xa = a.x() + t0 * (b.x() - a.x()), xb = a.x() + t1 * (b.x() - a.x());
        x0 = std::min(xa, xb);
        x1 = std::max(xa, xb);
      }
      const int first_column = ClampColumn(Column(x0 - padding_));
      const int last_column = ClampColumn(Column(x1 + padding_));
      for (int column_step = 0; column_step <= last_column - first_column; ++column_step) {
        const int column = columns_up ? first_column + column_step : last_column - column_step;
        const int cell = row * columns_ + column;
        for (int i = offsets_[cell]; i < offsets_[cell + 1]; ++i) {
          if (!visit(items_[i])) return false;
        }
      }
    }
    return true;
  }

 private:
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();
  double cell_size_ = 1;
  double padding_ = 0;
  int columns_ = 0, rows_ = 0;
  std::vector<int> offsets_;  // items of cell c: items_[offsets_[c] .. offsets_[c + 1])
  std::vector<int> items_;

  int Column(double x) const {
    return static_cast<int>(std::floor((x - origin_.x()) / cell_size_));
  }
  int Row(double y) const { return static_cast<int>(std::floor((y - origin_.y()) / cell_size_)); }
  int ClampColumn(int column) const { return std::clamp(column, 0, columns_ - 1); }
  int ClampRow(int row) const { return std::clamp(row, 0, rows_ - 1); }
  // Calls action(cell) for the cells that `box`, widened by the padding, overlaps.
  template <typename Action>
  void ForEachCellInBox(const Eigen::AlignedBox2d& box, Action action) const {
    const int first_row = ClampRow(Row(box.min().y() - padding_));
    const int last_row = ClampRow(Row(box.max().y() + padding_));
    const int first_column = ClampColumn(Column(box.min().x() - padding_));
    const int last_column = ClampColumn(Column(box.max().x() + padding_));
    for (int row = first_row; row <= last_row; ++row) {
      for (int column = first_column; column <= last_column; ++column) {
        action(row * columns_ + column);
      }
    }
  }
  template <typename Visit>
  void VisitCell(int cell, Visit& visit) const {
    for (int i = offsets_[cell]; i < offsets_[cell + 1]; ++i) visit(items_[i]);
  }
};

}  // namespace areagraph
