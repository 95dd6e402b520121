#include "tools/example_maps/benchmark_furniture.h"

#include <algorithm>
#include <utility>

namespace areagraph::floorplan {
namespace {

constexpr int kTries = 40;

bool Overlap(const RectM& a, const RectM& b) {
  return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

RectM Inflated(const RectM& r, double margin) {
  return {r.x - margin, r.y - margin, r.width + 2 * margin, r.height + 2 * margin};
}

bool Inside(const RectM& outer, const RectM& r) {
  return r.x >= outer.x && r.y >= outer.y && r.x + r.width <= outer.x + outer.width &&
         r.y + r.height <= outer.y + outer.height;
}

// Places furniture in one room, keeping doors clear and free-standing pieces
// apart from everything else.
class Furnisher {
 public:
  Furnisher(const RectM& inner, const std::vector<RectM>& keep_out, PortableRandom& random)
      : inner_(inner), keep_out_(keep_out), random_(random) {}

  std::vector<RectM> Take() { return std::move(placed_); }

  // A piece at least kFurnitureGapM from walls and other furniture.
  bool PlaceFree(double width, double height) {
    const RectM room = Inflated(inner_, -kFurnitureGapM);
    if (room.width < width || room.height < height) return false;
    for (int t = 0; t < kTries; ++t) {
      const RectM r{random_.Uniform(room.x, room.x + room.width - width),
                    random_.Uniform(room.y, room.y + room.height - height), width, height};
      if (TryAdd(r, kFurnitureGapM)) return true;
    }
    return false;
  }

  // A piece against wall `side` (0 top, 1 bottom, 2 left, 3 right), `length`
  // along it, `depth` into the room, starting `along` from the wall's start.
  RectM AgainstWall(int side, double along, double length, double depth) const {
    switch (side) {
      case 0:
        return {inner_.x + along, inner_.y, length, depth};
      case 1:
        return {inner_.x + along, inner_.y + inner_.height - depth, length, depth};
      case 2:
        return {inner_.x, inner_.y + along, depth, length};
      default:
        return {inner_.x + inner_.width - depth, inner_.y + along, depth, length};
    }
  }

  double WallLength(int side) const { return side < 2 ? inner_.width : inner_.height; }

  bool PlaceByWall(double length, double depth) {
    for (int t = 0; t < kTries; ++t) {
      const int side = random_.Int(0, 3);
      const double room = WallLength(side) - length;
      if (room < 0) continue;
      if (TryAdd(AgainstWall(side, random_.Uniform(0, room), length, depth), 0)) return true;
    }
    return false;
  }

  // Desks along every wall with gaps of 0.1-1 m between them.
  void Ring() {
    for (int side = 0; side < 4; ++side) {
      double along = random_.Uniform(0, 0.8);
      for (;;) {
        const double length = random_.Uniform(1.2, 1.8);
        if (along + length > WallLength(side)) break;
        TryAdd(AgainstWall(side, along, length, random_.Uniform(0.6, 0.8)), 0);
        along += length + random_.Uniform(0.1, 1.0);
      }
    }
  }

  // Blocks of two or four desks in rows, with aisles of 1-1.6 m.
  void Rows() {
    const double aisle = random_.Uniform(1.0, 1.6);
    const double block_w = random_.Uniform(1.4, 1.8) * random_.Int(1, 2);
    const double block_h = 2 * random_.Uniform(0.7, 0.8);
    for (double y = inner_.y + aisle; y + block_h + aisle <= inner_.y + inner_.height;
         y += block_h + aisle) {
      for (double x = inner_.x + aisle; x + block_w + aisle <= inner_.x + inner_.width;
           x += block_w + aisle) {
        TryAdd({x, y, block_w, block_h}, kFurnitureGapM);
      }
    }
  }

  PortableRandom& random() { return random_; }

  // Adds `r` when it lies inside the room, outside the keep-out boxes and at
  // least `gap` (or the other piece's gap) from every other piece.
  bool TryAdd(const RectM& r, double gap) {
    if (!Inside(inner_, r)) return false;
    for (const RectM& k : keep_out_) {
      if (Overlap(r, k)) return false;
    }
    for (const auto& [other, other_gap] : pieces_) {
      if (Overlap(Inflated(r, std::max(gap, other_gap)), other)) return false;
    }
    pieces_.emplace_back(r, gap);
    placed_.push_back(r);
    return true;
  }

 private:
  RectM inner_;
  const std::vector<RectM>& keep_out_;
  PortableRandom& random_;
  std::vector<std::pair<RectM, double>> pieces_;
  std::vector<RectM> placed_;
};

void FreeDesk(Furnisher& f) {
  double a = f.random().Uniform(1.2, 2.0), b = f.random().Uniform(0.6, 0.9);
  if (f.random().Chance(0.3)) b *= 2;  // two desks back to back
  if (f.random().Chance(0.5)) std::swap(a, b);
  f.PlaceFree(a, b);
}

void Cabinet(Furnisher& f) {
  f.PlaceByWall(f.random().Uniform(0.8, 2.0), f.random().Uniform(0.4, 0.6));
}

void WallDesk(Furnisher& f) {
  f.PlaceByWall(f.random().Uniform(1.2, 1.8), f.random().Uniform(0.6, 0.8));
}

}  // namespace

RectM InnerRect(const RectM& part, double wall_m) { return Inflated(part, -wall_m / 2); }

Furnishing RandomFurnishing(ZoneKind kind, PortableRandom& random) {
  if (kind == ZoneKind::kOpenPlan) return Furnishing::kDeskRows;
  // Seat rows and stair walls are the layout's fixtures.
  if (kind == ZoneKind::kLectureHall || kind == ZoneKind::kStairs) return Furnishing::kEmpty;
  if (kind == ZoneKind::kLobby) return Furnishing::kSeveralDesks;
  if (kind == ZoneKind::kBay) kind = ZoneKind::kHall;
  const double p = random.Uniform(0, 1);
  if (kind == ZoneKind::kHall) {
    return p < 0.2 ? Furnishing::kEmpty : p < 0.7 ? Furnishing::kSeveralDesks : Furnishing::kMixed;
  }
  if (p < 0.15) return Furnishing::kEmpty;
  if (p < 0.35) return Furnishing::kOneDesk;
  if (p < 0.50) return Furnishing::kSeveralDesks;
  if (p < 0.65) return Furnishing::kCabinetByWall;
  if (p < 0.80) return Furnishing::kDeskRing;
  return Furnishing::kMixed;
}

std::vector<RectM> FurnishRoom(const RectM& inner, Furnishing furnishing,
                               const std::vector<RectM>& keep_out, bool clutter,
                               PortableRandom& random) {
  Furnisher f(inner, keep_out, random);
  switch (furnishing) {
    case Furnishing::kEmpty:
      break;
    case Furnishing::kOneDesk:
      FreeDesk(f);
      break;
    case Furnishing::kSeveralDesks:
      for (int n = random.Int(2, 4); n > 0; --n) FreeDesk(f);
      break;
    case Furnishing::kCabinetByWall:
      for (int n = random.Int(1, 2); n > 0; --n) Cabinet(f);
      break;
    case Furnishing::kDeskRing:
      f.Ring();
      break;
    case Furnishing::kMixed:
      for (int n = random.Int(1, 2); n > 0; --n) WallDesk(f);
      FreeDesk(f);
      Cabinet(f);
      break;
    case Furnishing::kDeskRows:
      f.Rows();
      for (int n = random.Int(0, 3); n > 0; --n) Cabinet(f);
      break;
  }
  if (clutter) {
    const double bin = random.Uniform(0.3, 0.45);
    f.PlaceByWall(bin, bin);
    for (int n = random.Int(0, 3); n > 0; --n) f.PlaceFree(0.45, 0.45);  // chairs
  }
  return f.Take();
}

std::vector<RectM> FurnishCorridor(const RectM& inner, const std::vector<RectM>& keep_out,
                                   PortableRandom& random) {
  const bool horizontal = inner.width >= inner.height;
  if ((horizontal ? inner.height : inner.width) < 1.6) return {};
  Furnisher f(inner, keep_out, random);
  for (int n = random.Int(1, 3); n > 0; --n) {
    const bool bin = random.Chance(0.6);
    const double length = bin ? random.Uniform(0.3, 0.4) : random.Uniform(0.8, 1.5);
    const double depth = bin ? length : random.Uniform(0.35, 0.45);
    const int side = (horizontal ? 0 : 2) + random.Int(0, 1);
    const double room = f.WallLength(side) - length;
    if (room > 0) f.TryAdd(f.AgainstWall(side, random.Uniform(0, room), length, depth), 0);
  }
  return f.Take();
}

}  // namespace areagraph::floorplan
