#pragma once

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace areagraph {

// Points sorted into square buckets of side `bucket_size`, so that "is any
// stored point near this one" looks at the 3 x 3 buckets around it instead
// of every stored point: whatever lies closer than `bucket_size` to a point
// is in those nine. Which points count as near is the caller's test, so the
// answers are those of the scan over all points.
class PointBuckets {
 public:
  explicit PointBuckets(double bucket_size) : size_(bucket_size) {}

  void Add(double x, double y, int id) { buckets_[Key(Cell(x), Cell(y))].push_back(id); }

  // True when `near(id)` holds for some stored id in the nine buckets around
  // (x, y); `near` must only hold for points closer than the bucket size.
  template <typename Near>
  bool AnyNear(double x, double y, const Near& near) const {
    const int64_t cx = Cell(x), cy = Cell(y);
    for (int64_t dy = -1; dy <= 1; ++dy) {
      for (int64_t dx = -1; dx <= 1; ++dx) {
        const auto bucket = buckets_.find(Key(cx + dx, cy + dy));
        if (bucket == buckets_.end()) continue;
        for (const int id : bucket->second) {
          if (near(id)) return true;
        }
      }
    }
    return false;
  }

 private:
  // Bucket coordinates stay far inside 32 bits for any map (a bucket is
  // metres wide); non-finite or absurd coordinates share the edge bucket.
  int64_t Cell(double v) const {
    const double cell = std::floor(v / size_);
    return std::isfinite(cell) ? static_cast<int64_t>(std::fmax(-1e9, std::fmin(1e9, cell))) : 0;
  }
  static int64_t Key(int64_t cx, int64_t cy) { return cx * 4000000007LL + cy; }

  double size_;
  std::unordered_map<int64_t, std::vector<int>> buckets_;
};

}  // namespace areagraph
