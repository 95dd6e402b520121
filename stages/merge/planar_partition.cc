#include "stages/merge/planar_partition.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>
#ifdef __SSE2__
#include <immintrin.h>
#endif

namespace areagraph {
namespace {

// Directions out of a grid corner, clockwise on screen: the even ones run
// along cell edges (east, south, west, north), the odd ones are the short
// diagonal border between the two points of a cut corner.
constexpr int kEast = 0, kSouth = 2, kWest = 4, kNorth = 6;
constexpr int kSouthEast = 1, kSouthWest = 3, kNorthWest = 5, kNorthEast = 7;
constexpr int kDx[8] = {1, 1, 0, -1, -1, -1, 0, 1};
constexpr int kDy[8] = {0, 1, 1, 1, 0, -1, -1, -1};
// How far the point of a cut corner moves into its cell, along both axes (px).
constexpr double kCornerCut = 0.05;

int Reverse(int dir) { return (dir + 4) % 8; }
unsigned Bit(int dir) { return 1u << dir; }

enum class Cut {
  kNone,
  // The top-left and bottom-right cells are cut off the corner.
  kMainDiagonal,
  // The top-right and bottom-left cells are.
  kAntiDiagonal,
};

// The four cells around a grid corner and how the borders meet there.
struct Corner {
  int tl = 0, tr = 0, bl = 0, br = 0;
  Cut cut = Cut::kNone;
  // Bit d for each cell edge that is a border and leaves the corner in direction d.
  unsigned edges = 0;
  // Whether the two points of a cut corner are joined by a border (the two
  // cells between them differ).
  bool short_edge = false;
};

inline Corner MakeCorner(int tl, int tr, int bl, int br) {
  Corner corner{tl, tr, bl, br};
  if (tr != br) corner.edges |= Bit(kEast);
  if (bl != br) corner.edges |= Bit(kSouth);
  if (tl != bl) corner.edges |= Bit(kWest);
  if (tl != tr) corner.edges |= Bit(kNorth);
  const bool main_pair = tl == br && tl != tr && tl != bl;
  const bool anti_pair = tr == bl && tr != tl && tr != br;
  if (!main_pair && !anti_pair) return corner;
  // The pair that passes through the corner: no area (walls meeting at a
  // corner are one wall), else the lower label; an area pair that does not
  // pass is cut.
  bool main_passes;
  if (main_pair && anti_pair) {
    main_passes = tl == 0 || (tr != 0 && tl < tr);
  } else {
    main_passes = main_pair ? tl == 0 : tr != 0;
  }
  corner.cut = main_passes ? Cut::kAntiDiagonal : Cut::kMainDiagonal;
  corner.short_edge = main_passes ? tl != br : tr != bl;
  return corner;
}

// Which of a corner's points (0 or 1) the cell edge leaving in `dir` starts at.
int PointOf(const Corner& corner, int dir) {
  switch (corner.cut) {
    case Cut::kNone:
      return 0;
    case Cut::kMainDiagonal:
      return dir == kNorth || dir == kWest ? 0 : 1;
    case Cut::kAntiDiagonal:
      return dir == kNorth || dir == kEast ? 0 : 1;
  }
  return 0;
}

// The directions in which borders leave point `point` of a corner.
unsigned OutDirections(const Corner& corner, int point) {
  switch (corner.cut) {
    case Cut::kNone:
      return corner.edges;
    case Cut::kMainDiagonal:
      return point == 0 ? Bit(kNorth) | Bit(kWest) | (corner.short_edge ? Bit(kSouthEast) : 0)
                        : Bit(kEast) | Bit(kSouth) | (corner.short_edge ? Bit(kNorthWest) : 0);
    case Cut::kAntiDiagonal:
      return point == 0 ? Bit(kNorth) | Bit(kEast) | (corner.short_edge ? Bit(kSouthWest) : 0)
                        : Bit(kSouth) | Bit(kWest) | (corner.short_edge ? Bit(kNorthEast) : 0);
  }
  return 0;
}

// The cell on the right (on screen) of a border leaving a corner in `dir`.
int RightOf(const Corner& corner, int dir) {
  switch (dir) {
    case kEast:
    case kNorthEast:
      return corner.br;
    case kSouth:
    case kSouthEast:
      return corner.bl;
    case kWest:
    case kSouthWest:
      return corner.tl;
    default:  // north, north-west
      return corner.tr;
  }
}

// The cell on the left of a border leaving a corner in `dir`.
int LeftOf(const Corner& corner, int dir) {
  switch (dir) {
    case kEast:
    case kSouthEast:
      return corner.tr;
    case kSouth:
    case kSouthWest:
      return corner.br;
    case kWest:
    case kNorthWest:
      return corner.bl;
    default:  // north, north-east
      return corner.tl;
  }
}

// The set bits of a direction mask (below 256). The baseline x86-64 has no
// popcount instruction: __builtin_popcount is a library call.
int PopCount(unsigned bits) {
  bits = bits - ((bits >> 1) & 0x55u);
  bits = (bits & 0x33u) + ((bits >> 2) & 0x33u);
  return static_cast<int>((bits + (bits >> 4)) & 0x0Fu);
}
int LowestBit(unsigned bits) { return __builtin_ctz(bits); }

// Appends `point`, dropping the previous point when it lies on the straight
// line between its neighbours.
void AppendPoint(const Eigen::Vector2d& point, PointList* points) {
  const size_t n = points->size();
  if (n >= 2) {
    const Eigen::Vector2d u = (*points)[n - 1] - (*points)[n - 2], v = point - (*points)[n - 1];
    if (u.x() * v.y() - u.y() * v.x() == 0 && u.dot(v) > 0) {
      points->back() = point;
      return;
    }
  }
  points->push_back(point);
}

// A point of the planar map: point 0 or 1 of grid corner (x, y).
struct Vertex {
  int x = 0, y = 0, point = 0;
  bool operator==(const Vertex& other) const {
    return x == other.x && y == other.y && point == other.point;
  }
};

// Where a chain begins and ends.
struct ChainEnds {
  // A piece of a closed loop: its rings are linked when it is cut.
  bool loop = false;
  Vertex start, end;
  // Direction of the first step out of `start` and of the last step into `end`.
  int start_dir = 0, end_dir = 0;
};

// Chain sides by the dart (a DartKey, >= 0) they start with, in open
// addressing: an unordered_map allocated a node per dart.
class DartSides {
 public:
  DartSides() : keys_(kInitial, kEmpty), sides_(kInitial) {}

  const ChainSide* Find(int64_t key) const {
    for (size_t i = Home(key);; i = (i + 1) & (keys_.size() - 1)) {
      if (keys_[i] == key) return &sides_[i];
      if (keys_[i] == kEmpty) return nullptr;
    }
  }
  void Set(int64_t key, const ChainSide& side) {
    if (2 * (count_ + 1) > keys_.size()) Grow();
    size_t i = Home(key);
    while (keys_[i] != kEmpty && keys_[i] != key) i = (i + 1) & (keys_.size() - 1);
    if (keys_[i] == kEmpty) ++count_;
    keys_[i] = key;
    sides_[i] = side;
  }

 private:
  static constexpr int64_t kEmpty = -1;
  static constexpr size_t kInitial = 1024;
  size_t Home(int64_t key) const {
    uint64_t h = static_cast<uint64_t>(key) * 0x9E3779B97F4A7C15ull;
    return static_cast<size_t>(h ^ (h >> 29)) & (keys_.size() - 1);
  }
  void Grow() {
    std::vector<int64_t> keys(2 * keys_.size(), kEmpty);
    std::vector<ChainSide> sides(keys.size());
    keys.swap(keys_);
    sides.swap(sides_);
    count_ = 0;
    for (size_t i = 0; i < keys.size(); ++i) {
      if (keys[i] != kEmpty) Set(keys[i], sides[i]);
    }
  }
  std::vector<int64_t> keys_;
  std::vector<ChainSide> sides_;
  size_t count_ = 0;
};

class PartitionTracer {
 public:
  explicit PartitionTracer(const cv::Mat& labels)
      : labels_(labels),
        width_(labels.cols),
        height_(labels.rows),
        visited_(static_cast<size_t>(width_ + 1) * (height_ + 1), 0) {}

  PlanarPartition Trace(int label_count) {
    partition_.rings.assign(label_count, {});
    TraceChainsBetweenJunctions();
    TraceClosedLoops();
    LinkRings(label_count);
    return std::move(partition_);
  }

 private:
  int Label(int c, int r) const {
    return c < 0 || r < 0 || c >= width_ || r >= height_ ? 0 : labels_.at<int>(r, c);
  }
  Corner CornerAt(int x, int y) const {
    return MakeCorner(Label(x - 1, y - 1), Label(x, y - 1), Label(x - 1, y), Label(x, y));
  }
  size_t CornerIndex(int x, int y) const { return static_cast<size_t>(y) * (width_ + 1) + x; }
  int64_t DartKey(const Vertex& v, int dir) const {
    return (static_cast<int64_t>(CornerIndex(v.x, v.y)) * 2 + v.point) * 8 + dir;
  }

  static Eigen::Vector2d Position(const Vertex& v, const Corner& corner) {
    const Eigen::Vector2d at(v.x, v.y);
    switch (corner.cut) {
      case Cut::kNone:
        return at;
      case Cut::kMainDiagonal:
        return at + (v.point == 0 ? -kCornerCut : kCornerCut) * Eigen::Vector2d(1, 1);
      case Cut::kAntiDiagonal:
        return at + (v.point == 0 ? kCornerCut : -kCornerCut) * Eigen::Vector2d(1, -1);
    }
    return at;
  }

  // Whether the nine cells from `above` and from `below` all hold above[0]
  // (the eight corners between them meet no border).
  static bool Uniform(const int* above, const int* below) {
#ifdef __SSE2__
    const __m128i same = _mm_set1_epi32(above[0]);
    auto equal = [&](const int* p) {
      return _mm_cmpeq_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)), same);
    };
    const __m128i all = _mm_and_si128(_mm_and_si128(equal(above), equal(above + 4)),
                                      _mm_and_si128(equal(below), equal(below + 4)));
    return _mm_movemask_epi8(all) == 0xFFFF && above[8] == above[0] && below[8] == above[0];
#else
    int differ = 0;
    for (int i = 0; i < 9; ++i) differ |= (above[i] ^ above[0]) | (below[i] ^ above[0]);
    return differ == 0;
#endif
  }

  // Calls visit(x, y, corner) for every grid corner where borders meet,
  // reading each label row once.
  template <typename Visit>
  void ForEachBorderCorner(Visit visit) const {
    std::vector<int> none(width_, 0);
    for (int y = 0; y <= height_; ++y) {
      const int* above = y > 0 ? labels_.ptr<int>(y - 1) : none.data();
      const int* below = y < height_ ? labels_.ptr<int>(y) : none.data();
      for (int x = 0; x <= width_; ++x) {
        // Eight corners at once where the two rows hold one label across
        // nine cells (most of the map).
        while (x > 0 && x + 8 < width_ && Uniform(above + x - 1, below + x - 1)) x += 8;
        const int tl = x > 0 ? above[x - 1] : 0, tr = x < width_ ? above[x] : 0;
        const int bl = x > 0 ? below[x - 1] : 0, br = x < width_ ? below[x] : 0;
        if (tl == tr && tl == bl && tl == br) continue;
        visit(x, y, MakeCorner(tl, tr, bl, br));
      }
    }
  }

  void MarkVisited(const Vertex& from, int dir) {
    switch (dir) {
      case kEast:
        visited_[CornerIndex(from.x, from.y)] |= 1;
        break;
      case kSouth:
        visited_[CornerIndex(from.x, from.y)] |= 2;
        break;
      case kWest:
        visited_[CornerIndex(from.x - 1, from.y)] |= 1;
        break;
      case kNorth:
        visited_[CornerIndex(from.x, from.y - 1)] |= 2;
        break;
      default:  // the short diagonal borders are not cell edges
        break;
    }
  }

  // Follows the border leaving `start` in `dir` through points where only
  // two borders meet, up to a junction (or back to `start` when `loop`).
  // Returns the points and sets `ends`.
  PointList Walk(const Vertex& start, const Corner& start_corner, int dir, bool loop,
                 ChainEnds* ends) {
    // The points go to a buffer that keeps its capacity from walk to walk,
    // and leave it in one allocation of their own size.
    PointList& points = walk_points_;
    points.assign(1, Position(start, start_corner));
    ends->start = start;
    ends->start_dir = dir;
    Vertex at = start;
    for (;;) {
      MarkVisited(at, dir);
      Vertex next = at;
      Corner corner;
      if (dir % 2 == 1) {
        corner = CornerAt(at.x, at.y);
        next.point = 1 - at.point;
      } else {
        next.x += kDx[dir];
        next.y += kDy[dir];
        corner = CornerAt(next.x, next.y);
        next.point = PointOf(corner, Reverse(dir));
      }
      AppendPoint(Position(next, corner), &points);
      const unsigned out = OutDirections(corner, next.point);
      if (loop && PopCount(out) != 2) throw std::logic_error("closed border with a junction");
      if (PopCount(out) != 2 || (loop && next == start)) {
        ends->end = next;
        ends->end_dir = dir;
        return PointList(points.begin(), points.end());
      }
      dir = LowestBit(out & ~Bit(Reverse(dir)));
      at = next;
    }
  }

  void TraceChainsBetweenJunctions() {
    ForEachBorderCorner([&](int x, int y, const Corner& corner) {
      border_corners_.push_back({x, y, corner.edges});
      for (int point = 0; point < (corner.cut == Cut::kNone ? 1 : 2); ++point) {
        const unsigned out = OutDirections(corner, point);
        if (PopCount(out) == 2) continue;
        const Vertex start{x, y, point};
        for (int dir = 0; dir < 8; ++dir) {
          // A dart is used once a chain starts or ends with it.
          if (!(out & Bit(dir)) || side_from_.Find(DartKey(start, dir))) continue;
          ChainEnds ends;
          BorderChain chain;
          chain.points = Walk(start, corner, dir, /*loop=*/false, &ends);
          chain.right = RightOf(corner, dir);
          chain.left = LeftOf(corner, dir);
          const int index = static_cast<int>(partition_.chains.size());
          side_from_.Set(DartKey(start, dir), {index, false});
          side_from_.Set(DartKey(ends.end, Reverse(ends.end_dir)), {index, true});
          partition_.chains.push_back(std::move(chain));
          ends_.push_back(ends);
        }
      }
    });
  }

  // Borders without a junction (an island inside one area, an area with a
  // single neighbour all round) are closed loops. Each is cut into three
  // chains at points of its convex hull, so that simplification keeps at
  // least a triangle.
  void TraceClosedLoops() {
    for (const BorderCorner& at : border_corners_) {
      const int x = at.x, y = at.y;
      // Most corners' borders were walked between junctions: their corner
      // is not built again.
      const uint8_t walked = visited_[CornerIndex(x, y)];
      if (!((at.edges & Bit(kEast)) && !(walked & 1)) &&
          !((at.edges & Bit(kSouth)) && !(walked & 2))) {
        continue;
      }
      const Corner corner = CornerAt(x, y);
      for (const int dir : {kEast, kSouth}) {
        const uint8_t bit = dir == kEast ? 1 : 2;
        if (!(corner.edges & Bit(dir)) || (visited_[CornerIndex(x, y)] & bit)) continue;
        const Vertex start{x, y, PointOf(corner, dir)};
        ChainEnds ends;
        PointList loop = Walk(start, corner, dir, /*loop=*/true, &ends);
        loop.pop_back();  // the start again
        AddLoop(WithoutCollinearPoints(loop), RightOf(corner, dir), LeftOf(corner, dir));
      }
    }
  }

  static PointList WithoutCollinearPoints(const PointList& ring) {
    PointList out;
    const size_t n = ring.size();
    for (size_t i = 0; i < n; ++i) {
      const Eigen::Vector2d u = ring[i] - ring[(i + n - 1) % n], v = ring[(i + 1) % n] - ring[i];
      if (u.x() * v.y() - u.y() * v.x() == 0 && u.dot(v) > 0) continue;
      out.push_back(ring[i]);
    }
    return out;
  }

  void AddLoop(const PointList& loop, int right, int left) {
    const size_t n = loop.size();
    if (n < 3) throw std::logic_error("closed border with fewer than three corners");
    size_t first = 0;
    for (size_t i = 1; i < n; ++i) {
      if (loop[i].y() < loop[first].y() ||
          (loop[i].y() == loop[first].y() && loop[i].x() < loop[first].x())) {
        first = i;
      }
    }
    size_t far = first;
    for (size_t i = 0; i < n; ++i) {
      if ((loop[i] - loop[first]).squaredNorm() > (loop[far] - loop[first]).squaredNorm()) far = i;
    }
    const Eigen::Vector2d axis = loop[far] - loop[first];
    size_t third = n;
    double best = -1;
    for (size_t i = 0; i < n; ++i) {
      if (i == first || i == far) continue;
      const Eigen::Vector2d d = loop[i] - loop[first];
      const double off = std::abs(axis.x() * d.y() - axis.y() * d.x());
      if (off > best) best = off, third = i;
    }
    size_t cuts[3] = {first, far, third};
    std::sort(cuts, cuts + 3);
    const int base = static_cast<int>(partition_.chains.size());
    for (int k = 0; k < 3; ++k) {
      BorderChain chain{{}, right, left};
      for (size_t i = cuts[k];; i = (i + 1) % n) {
        chain.points.push_back(loop[i]);
        if (i == cuts[(k + 1) % 3] && chain.points.size() > 1) break;
      }
      partition_.chains.push_back(std::move(chain));
      ChainEnds ends;
      ends.loop = true;
      ends_.push_back(ends);
    }
    if (right > 0) {
      partition_.rings[right - 1].push_back({{base, false}, {base + 1, false}, {base + 2, false}});
    }
    if (left > 0) {
      partition_.rings[left - 1].push_back({{base + 2, true}, {base + 1, true}, {base, true}});
    }
  }

  // The side that follows `side` around the region on its right: at the
  // junction where it ends, the next border counter-clockwise (on screen).
  ChainSide NextSide(const ChainSide& side) const {
    const ChainEnds& ends = ends_[side.chain];
    const Vertex at = side.reversed ? ends.start : ends.end;
    const int arrival = side.reversed ? Reverse(ends.start_dir) : ends.end_dir;
    const unsigned out = OutDirections(CornerAt(at.x, at.y), at.point);
    const int back = Reverse(arrival);
    for (int turn = 1; turn < 8; ++turn) {
      const int dir = (back + 8 - turn) % 8;
      if (!(out & Bit(dir))) continue;
      const ChainSide* side = side_from_.Find(DartKey(at, dir));
      if (side == nullptr) break;
      return *side;
    }
    throw std::logic_error("planar partition: a border chain has no successor");
  }

  void LinkRings(int label_count) {
    std::vector<bool> used(2 * partition_.chains.size(), false);
    for (size_t c = 0; c < partition_.chains.size(); ++c) {
      if (ends_[c].loop) continue;
      for (const bool reversed : {false, true}) {
        const BorderChain& chain = partition_.chains[c];
        const int label = reversed ? chain.left : chain.right;
        if (label <= 0 || label > label_count || used[2 * c + reversed]) continue;
        std::vector<ChainSide> ring;
        ChainSide side{static_cast<int>(c), reversed};
        do {
          if (used[2 * side.chain + side.reversed]) {
            throw std::logic_error("planar partition: rings overlap");
          }
          used[2 * side.chain + side.reversed] = true;
          ring.push_back(side);
          side = NextSide(side);
        } while (side.chain != static_cast<int>(c) || side.reversed != reversed);
        partition_.rings[label - 1].push_back(std::move(ring));
      }
    }
  }

  const cv::Mat& labels_;
  const int width_, height_;
  // Bit 0: the cell edge east of a corner was walked; bit 1: the one south.
  std::vector<uint8_t> visited_;
  PlanarPartition partition_;
  // Per chain.
  std::vector<ChainEnds> ends_;
  // Every grid corner where borders meet, in row order, with its cell-edge borders (Corner.edges).
  struct BorderCorner {
    int x, y;
    unsigned edges;
  };
  std::vector<BorderCorner> border_corners_;
  DartSides side_from_;
  PointList walk_points_;
};

}  // namespace

PlanarPartition BuildPlanarPartition(const cv::Mat& labels, int label_count) {
  CV_Assert(labels.type() == CV_32S);
  return PartitionTracer(labels).Trace(label_count);
}

PointList RingPoints(const std::vector<ChainSide>& ring,
                     const std::vector<PointList>& chain_points) {
  PointList points;
  size_t total = 0;
  for (const ChainSide& side : ring) total += chain_points[side.chain].size();
  points.reserve(total);
  for (const ChainSide& side : ring) {
    const PointList& chain = chain_points[side.chain];
    const size_t n = chain.size();
    // Each chain's first point is the previous one's last.
    for (size_t i = 0; i + 1 < n; ++i) points.push_back(chain[side.reversed ? n - 1 - i : i]);
  }
  return points;
}

std::vector<PointList> ChainPoints(const PlanarPartition& partition) {
  std::vector<PointList> points;
  points.reserve(partition.chains.size());
  for (const BorderChain& chain : partition.chains) points.push_back(chain.points);
  return points;
}

}  // namespace areagraph
