#include "tools/example_maps/benchmark_layout.h"

#include <algorithm>
#include <limits>

namespace areagraph::floorplan {
namespace {

// Doors keep this far from the corners of the wall they are cut into (m).
constexpr double kDoorCornerM = 0.3;

// A straight stretch of corridor (or a hall) that rooms line up along.
struct Arm {
  RectM rect;
  bool horizontal = true;
  int zone = 0;
};

class LayoutBuilder : public LayoutCanvas {
 public:
  explicit LayoutBuilder(PortableRandom& random) : random_(random) {}

  double DoorWidth() { return random_.Uniform(kMinDoorM, kMaxDoorM); }

  // A door somewhere on the wall segment from `from` to `to` (along the
  // wall), at `across` on the other axis.
  void AddDoor(double from, double to, double across, WallDirection wall) {
    double width = DoorWidth();
    const double room = to - from - 2 * kDoorCornerM;
    if (room < kMinDoorM) return;
    width = std::min(width, room);
    const double centre =
        random_.Uniform(from + kDoorCornerM + width / 2, to - kDoorCornerM - width / 2);
    if (wall == WallDirection::kHorizontal) {
      layout_.doors.push_back({centre, across, width, wall});
    } else {
      layout_.doors.push_back({across, centre, width, wall});
    }
  }

  // Rooms side by side along one side (-1: top or left, +1: bottom or right)
  // of `arm`, `depth` deep, each with a door into the arm's zone; some
  // neighbours get a door between them, and a few rooms are halls or
  // open-plan offices.
  void RoomRow(const Arm& arm, int side, double depth) {
    const RectM& a = arm.rect;
    const double length = arm.horizontal ? a.width : a.height;
    double s = 0;
    int previous = -1;
    double previous_depth = 0;
    while (length - s >= kMinRoomM) {
      double width =
          random_.Chance(0.12) ? random_.Uniform(kMinRoomM, 2.6) : random_.Uniform(2.6, 6.0);
      double room_depth = depth;
      ZoneKind kind = ZoneKind::kRoom;
      if (random_.Chance(0.1)) {
        kind = random_.Chance(0.5) ? ZoneKind::kOpenPlan : ZoneKind::kHall;
        width = random_.Uniform(8.0, kMaxRoomM);
        room_depth = std::min(kMaxRoomM, depth + random_.Uniform(1.0, 5.0));
      }
      if (length - s - width < kMinRoomM) width = length - s;  // no sliver at the end
      if (width > kMaxRoomM) width = random_.Uniform(3.0, 6.0);
      RectM room;
      if (arm.horizontal) {
        room = {a.x + s, side < 0 ? a.y - room_depth : a.y + a.height, width, room_depth};
      } else {
        room = {side < 0 ? a.x - room_depth : a.x + a.width, a.y + s, room_depth, width};
      }
      if (!Free(room)) {
        s += 1.0;
        previous = -1;
        continue;
      }
      const int zone = AddZone(kind, {room});
      if (arm.horizontal) {
        AddDoor(room.x, room.x + room.width, side < 0 ? a.y : a.y + a.height,
                WallDirection::kHorizontal);
      } else {
        AddDoor(room.y, room.y + room.height, side < 0 ? a.x : a.x + a.width,
                WallDirection::kVertical);
      }
      if (previous >= 0 && random_.Chance(0.25)) {
        // The wall between this room and the previous one, from the arm out.
        const double shared = std::min(room_depth, previous_depth);
        if (arm.horizontal) {
          const double from = side < 0 ? a.y - shared : a.y + a.height;
          AddDoor(from, from + shared, room.x, WallDirection::kVertical);
        } else {
          const double from = side < 0 ? a.x - shared : a.x + a.width;
          AddDoor(from, from + shared, room.y, WallDirection::kHorizontal);
        }
      }
      previous = zone;
      previous_depth = room_depth;
      s += width;
    }
  }

  double SideDepth() { return random_.Uniform(3.0, 7.0); }

 private:
  PortableRandom& random_;
};

void CorridorFloor(PortableRandom& random, LayoutBuilder& builder) {
  FloorLayout& layout = builder.layout();
  const double c = random.Uniform(kMinCorridorM, kMaxCorridorM);
  layout.corridor_width_m = c;
  std::vector<Arm> arms;
  std::vector<std::pair<int, int>> rows;  // (arm, side)
  const int kind = random.Int(0, 4);
  if (kind == 0 || kind == 1) {
    layout.name = kind == 0 ? "two-sided corridor" : "one-sided corridor";
    arms.push_back({{0, 0, random.Uniform(12, 30), c}, true});
    rows = {{0, -1}};
    if (kind == 0) rows.push_back({0, 1});
  } else if (kind == 2) {
    layout.name = "L corridor";
    const double l1 = random.Uniform(10, 24), l2 = random.Uniform(8, 20);
    arms.push_back({{0, 0, l1, c}, true});
    arms.push_back({{l1 - c, 0, c, l2}, false});
    rows = {{0, -1}, {0, 1}, {1, -1}, {1, 1}};
  } else if (kind == 3) {
    layout.name = "T corridor";
    const double l1 = random.Uniform(14, 28), l2 = random.Uniform(6, 16);
    const double stem = random.Chance(0.5) ? c : random.Uniform(kMinCorridorM, kMaxCorridorM);
    const double x = random.Uniform(0.3 * l1, 0.7 * l1 - stem);
    arms.push_back({{0, 0, l1, c}, true});
    arms.push_back({{x, 0, stem, c + l2}, false});
    rows = {{0, -1}, {0, 1}, {1, -1}, {1, 1}};
  } else {
    layout.name = "corridor with a dead end";
    const double l1 = random.Uniform(12, 28);
    const double branch = random.Uniform(kMinCorridorM, c);
    const double x = random.Uniform(0.2 * l1, 0.8 * l1 - branch);
    arms.push_back({{0, 0, l1, c}, true});
    arms.push_back({{x, 0, branch, c + random.Uniform(3, 7)}, false});
    rows = {{0, -1}, {0, 1}};
  }
  std::vector<RectM> parts;
  for (const Arm& arm : arms) parts.push_back(arm.rect);
  const int corridor = builder.AddZone(ZoneKind::kCorridor, parts);
  for (Arm& arm : arms) arm.zone = corridor;
  for (const auto& [arm, side] : rows) builder.RoomRow(arms[arm], side, builder.SideDepth());
}

void HallFloor(PortableRandom& random, LayoutBuilder& builder) {
  builder.layout().name = "hall";
  const Arm hall{{0, 0, random.Uniform(9, kMaxRoomM), random.Uniform(7, 12)}, true};
  builder.AddZone(ZoneKind::kHall, {hall.rect});
  builder.RoomRow(hall, -1, builder.SideDepth());
  builder.RoomRow(hall, 1, builder.SideDepth());
  if (random.Chance(0.6)) {
    const Arm side{hall.rect, false};
    builder.RoomRow(side, random.Chance(0.5) ? -1 : 1, builder.SideDepth());
  }
}

}  // namespace

const char* GroundTruthKindName(ZoneKind kind) {
  switch (kind) {
    case ZoneKind::kCorridor:
      return "corridor";
    case ZoneKind::kDeadEnd:
      return "dead_end";
    default:
      return "room";
  }
}

bool IsCorridorKind(ZoneKind kind) {
  return kind == ZoneKind::kCorridor || kind == ZoneKind::kDeadEnd;
}

int LayoutCanvas::AddZone(ZoneKind kind, std::vector<RectM> parts) {
  layout_.zones.push_back({kind, std::move(parts)});
  return static_cast<int>(layout_.zones.size()) - 1;
}

bool LayoutCanvas::Free(const RectM& rect) const {
  for (const Zone& zone : layout_.zones) {
    for (const RectM& part : zone.parts) {
      if (RectsOverlap(rect, part)) return false;
    }
  }
  for (const RectM& shaft : layout_.shafts) {
    if (RectsOverlap(rect, shaft)) return false;
  }
  return true;
}

bool RectsOverlap(const RectM& a, const RectM& b) {
  constexpr double kTouch = 0.05;  // shared walls are no overlap
  return a.x + kTouch < b.x + b.width && b.x + kTouch < a.x + a.width &&
         a.y + kTouch < b.y + b.height && b.y + kTouch < a.y + a.height;
}

// Moves everything so that the drawing starts 1 m from the plan's top-left
// corner, and sets the plan's size.
void FrameLayout(FloorLayout* layout) {
  constexpr double kMarginM = 1.0;
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const Zone& zone : layout->zones) {
    for (const RectM& p : zone.parts) {
      x0 = std::min(x0, p.x), y0 = std::min(y0, p.y);
      x1 = std::max(x1, p.x + p.width), y1 = std::max(y1, p.y + p.height);
    }
  }
  const double dx = kMarginM - x0, dy = kMarginM - y0;
  for (Zone& zone : layout->zones) {
    for (RectM& p : zone.parts) p.x += dx, p.y += dy;
  }
  for (DoorM& door : layout->doors) door.x += dx, door.y += dy;
  for (RectM& r : layout->fixtures) r.x += dx, r.y += dy;
  for (RectM& r : layout->shafts) r.x += dx, r.y += dy;
  layout->width_m = x1 - x0 + 2 * kMarginM;
  layout->height_m = y1 - y0 + 2 * kMarginM;
}

FloorLayout RandomFloorLayout(PortableRandom& random) {
  LayoutBuilder builder(random);
  if (random.Chance(0.2)) {
    HallFloor(random, builder);
  } else {
    CorridorFloor(random, builder);
  }
  FloorLayout layout = std::move(builder.layout());
  FrameLayout(&layout);
  return layout;
}

}  // namespace areagraph::floorplan
