#include "tools/route/cell_index.h"

namespace areagraph {

CellIndex::CellIndex(const std::vector<Eigen::AlignedBox2d>& boxes, double cell_size,
                     double padding)
    : cell_size_(cell_size), padding_(padding) {
  Eigen::AlignedBox2d bounds;
  for (const Eigen::AlignedBox2d& box : boxes) bounds.extend(box);
  if (boxes.empty() || bounds.isEmpty()) return;
  origin_ = bounds.min() - Eigen::Vector2d::Constant(padding);
  // At most 4096 cells a side, whatever the cell size asked for.
  const Eigen::Vector2d size = bounds.sizes() + Eigen::Vector2d::Constant(2 * padding);
  cell_size_ = std::max({cell_size, size.x() / 4096, size.y() / 4096, 1e-6});
  columns_ = static_cast<int>(size.x() / cell_size_) + 1;
  rows_ = static_cast<int>(size.y() / cell_size_) + 1;
  // Two passes: count the items per cell, then place them.
  offsets_.assign(static_cast<size_t>(columns_) * rows_ + 1, 0);
  for (const Eigen::AlignedBox2d& box : boxes) {
    if (!box.isEmpty()) ForEachCellInBox(box, [&](int cell) { ++offsets_[cell + 1]; });
  }
  for (size_t cell = 1; cell < offsets_.size(); ++cell) offsets_[cell] += offsets_[cell - 1];
  items_.resize(offsets_.back());
  std::vector<int> filled(offsets_.begin(), offsets_.end() - 1);
  for (size_t item = 0; item < boxes.size(); ++item) {
    if (boxes[item].isEmpty()) continue;
    ForEachCellInBox(boxes[item],
                     [&](int cell) { items_[filled[cell]++] = static_cast<int>(item); });
  }
}

}  // namespace areagraph
