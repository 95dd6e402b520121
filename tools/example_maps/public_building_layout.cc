#include "tools/example_maps/public_building_layout.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace areagraph::floorplan {
namespace {

// Doors keep this far from the corners of the wall they are cut into (m).
constexpr double kCornerM = 0.3;
// Rooms along a corridor are at least this wide (m).
constexpr double kMinRowRoomM = 1.8;

// A straight corridor (or the lobby) that rooms line up along. Places
// beside it are given by `along` (from its top or left end) and `out` (the
// distance from its wall on `side`: -1 top or left, +1 bottom or right).
struct Arm {
  RectM rect;
  bool horizontal = true;
  double Length() const { return horizontal ? rect.width : rect.height; }
};

// The rectangle beside `arm` on `side` between along0..along1 and out0..out1.
RectM Beside(const Arm& arm, int side, double along0, double along1, double out0, double out1) {
  const RectM& a = arm.rect;
  if (arm.horizontal) {
    const double y = side < 0 ? a.y - out1 : a.y + a.height + out0;
    return {a.x + along0, y, along1 - along0, out1 - out0};
  }
  const double x = side < 0 ? a.x - out1 : a.x + a.width + out0;
  return {x, a.y + along0, out1 - out0, along1 - along0};
}

class PublicBuilder : public LayoutCanvas {
 public:
  explicit PublicBuilder(PortableRandom& random) : random_(random) {}

  // A door `width` wide somewhere on the wall from `from` to `to` (along the
  // wall), at `across` on the other axis, `corner` from the wall's ends.
  void AddDoor(double from, double to, double across, WallDirection wall, double width,
               double corner = kCornerM) {
    const double room = to - from - 2 * corner;
    if (room < 0.7) return;
    width = std::min(width, room);
    const double centre = random_.Uniform(from + corner + width / 2, to - corner - width / 2);
    if (wall == WallDirection::kHorizontal) {
      layout_.doors.push_back({centre, across, width, wall});
    } else {
      layout_.doors.push_back({across, centre, width, wall});
    }
  }

  // The whole wall from `from` to `to` open.
  void OpenSide(double from, double to, double across, WallDirection wall) {
    const double centre = 0.5 * (from + to);
    if (wall == WallDirection::kHorizontal) {
      layout_.doors.push_back({centre, across, to - from, wall, true});
    } else {
      layout_.doors.push_back({across, centre, to - from, wall, true});
    }
  }

  // A door in the arm's wall on `side`, between along0 and along1.
  void DoorOnArm(const Arm& arm, int side, double along0, double along1, double width,
                 double corner = kCornerM) {
    const RectM& a = arm.rect;
    if (arm.horizontal) {
      AddDoor(a.x + along0, a.x + along1, side < 0 ? a.y : a.y + a.height,
              WallDirection::kHorizontal, width, corner);
    } else {
      AddDoor(a.y + along0, a.y + along1, side < 0 ? a.x : a.x + a.width, WallDirection::kVertical,
              width, corner);
    }
  }

  void OpenOnArm(const Arm& arm, int side, double along0, double along1) {
    const RectM& a = arm.rect;
    if (arm.horizontal) {
      OpenSide(a.x + along0, a.x + along1, side < 0 ? a.y : a.y + a.height,
               WallDirection::kHorizontal);
    } else {
      OpenSide(a.y + along0, a.y + along1, side < 0 ? a.x : a.x + a.width,
               WallDirection::kVertical);
    }
  }

  // A door in the wall across the arm's side at `along`, between out0 and
  // out1 from the arm.
  void DoorAcrossArm(const Arm& arm, int side, double along, double out0, double out1,
                     double width) {
    const RectM r = Beside(arm, side, along, along, out0, out1);
    if (arm.horizontal) {
      AddDoor(r.y, r.y + r.height, r.x, WallDirection::kVertical, width, 0.2);
    } else {
      AddDoor(r.x, r.x + r.width, r.y, WallDirection::kHorizontal, width, 0.2);
    }
  }

  double SingleDoor() { return random_.Uniform(kMinSingleDoorM, kMaxSingleDoorM); }
  double DoubleDoor() { return random_.Uniform(kMinDoubleDoorM, kMaxDoubleDoorM); }

  // Rooms along one side of a wing corridor (or of the lobby), `depth`
  // deep. Returns nothing; rooms that do not fit are skipped.
  void Row(const Arm& arm, int side, double depth, double corridor_width, bool lobby) {
    const double length = arm.Length();
    double along = 0;
    bool dead_end_done = lobby;
    while (length - along >= kMinRowRoomM) {
      const double p = random_.Uniform(0, 1);
      double used = 0;
      if (lobby) {
        if (p < 0.45) {
          used = Bay(arm, side, along, depth);
        } else if (p < 0.6) {
          used = Stairs(arm, side, along, depth);
        } else if (p < 0.75) {
          used = Lifts(arm, side, along, depth);
        } else {
          used = Room(arm, side, along, depth, random_.Uniform(6, 12), ZoneKind::kHall, true);
        }
      } else if (p < 0.5) {
        used = Room(arm, side, along, depth, random_.Uniform(3, 6), ZoneKind::kRoom, false);
      } else if (p < 0.62) {
        used = Room(arm, side, along, depth + random_.Uniform(0, 3), random_.Uniform(7, 14),
                    random_.Chance(0.5) ? ZoneKind::kHall : ZoneKind::kOpenPlan, true);
      } else if (p < 0.74) {
        used = Room(arm, side, along, depth, random_.Uniform(1.8, 3.0), ZoneKind::kRoom, false);
      } else if (p < 0.8) {
        used = Stairs(arm, side, along, depth);
      } else if (p < 0.86) {
        used = Lifts(arm, side, along, depth);
      } else if (p < 0.93 && corridor_width >= 2.5) {
        used = Bay(arm, side, along, depth);
      } else if (!dead_end_done && depth >= 5) {
        used = DeadEndBlock(arm, side, along, depth);
        dead_end_done = used > 0;
      } else {
        used = Room(arm, side, along, depth, random_.Uniform(3, 6), ZoneKind::kRoom, false);
      }
      along += used > 0 ? used : 1.0;
    }
  }

  // Lecture halls below the lobby: one or two halls with rows of seats on
  // either side of an aisle corridor that runs down from the lobby and on
  // along the halls' back.
  void LectureBlock(const RectM& lobby) {
    const double aisle = random_.Uniform(2.0, 3.5);
    const double depth = random_.Uniform(14, 22);
    const double xa = lobby.x + random_.Uniform(0.25, 0.75) * (lobby.width - aisle);
    const double top = lobby.y + lobby.height;
    const bool two = random_.Chance(0.6);
    const double left_w = random_.Uniform(14, 22);
    const double right_w = two ? random_.Uniform(14, 22) : 0;
    const double x0 = xa - left_w, x1 = xa + aisle + right_w;
    const RectM down{xa, top, aisle, depth + aisle};
    const RectM back{x0, top + depth, x1 - x0, aisle};
    if (!Free(down) || !Free(back)) return;
    AddZone(ZoneKind::kCorridor, {down, back});
    OpenOrFireDoor(xa, xa + aisle, top, WallDirection::kHorizontal, aisle);
    Hall({x0, top, left_w, depth}, /*aisle_on_right=*/true);
    if (two) Hall({xa + aisle, top, right_w, depth}, /*aisle_on_right=*/false);
  }

  // Where a corridor `width` wide meets a hall: open along its whole width
  // or a double fire door.
  void OpenOrFireDoor(double from, double to, double across, WallDirection wall, double width) {
    if (width < 2.0 || random_.Chance(0.6)) {
      OpenSide(from, to, across, wall);
    } else {
      AddDoor(from, to, across, wall,
              random_.Uniform(kMinDoubleDoorM, std::min(kMaxDoubleDoorM, width - 0.3)), 0.1);
    }
  }

  // A corridor of a wing, from the lobby's wall out.
  Arm WingCorridor(const RectM& lobby, int direction, double width, double length) {
    Arm arm;
    if (direction == 0) {  // left
      const double y = lobby.y + random_.Uniform(0.3, 0.7) * lobby.height - width / 2;
      arm = {{lobby.x - length, y, length, width}, true};
      OpenOrFireDoor(y, y + width, lobby.x, WallDirection::kVertical, width);
    } else if (direction == 1) {  // right
      const double y = lobby.y + random_.Uniform(0.3, 0.7) * lobby.height - width / 2;
      arm = {{lobby.x + lobby.width, y, length, width}, true};
      OpenOrFireDoor(y, y + width, lobby.x + lobby.width, WallDirection::kVertical, width);
    } else {  // up
      const double x = lobby.x + random_.Uniform(0.15, 0.85) * (lobby.width - width);
      arm = {{x, lobby.y - length, width, length}, false};
      OpenOrFireDoor(x, x + width, lobby.y, WallDirection::kHorizontal, width);
    }
    AddZone(ZoneKind::kCorridor, {arm.rect});
    return arm;
  }

  // Pillars in a grid, at least 3.5 m from the lobby's walls.
  void Pillars(const RectM& lobby) {
    const double spacing = random_.Uniform(6, 8), size = random_.Uniform(0.4, 0.7);
    constexpr double kMarginM = 3.5;
    for (double y = lobby.y + kMarginM; y + size <= lobby.y + lobby.height - kMarginM;
         y += spacing) {
      for (double x = lobby.x + kMarginM; x + size <= lobby.x + lobby.width - kMarginM;
           x += spacing) {
        layout_.fixtures.push_back({x, y, size, size});
      }
    }
  }

 private:
  // One room `width` along the arm (less where the arm ends), with a single
  // or a double door (and a second door on wide ones).
  double Room(const Arm& arm, int side, double along, double depth, double width, ZoneKind kind,
              bool double_door) {
    width = FitWidth(arm, along, width);
    const RectM room = Beside(arm, side, along, along + width, 0, depth);
    if (!Free(room)) return 0;
    AddZone(kind, {room});
    if (width > 10 && random_.Chance(0.6)) {
      DoorOnArm(arm, side, along, along + width / 2, double_door ? DoubleDoor() : SingleDoor());
      DoorOnArm(arm, side, along + width / 2, along + width, SingleDoor());
    } else {
      DoorOnArm(arm, side, along, along + width, double_door ? DoubleDoor() : SingleDoor());
    }
    return width;
  }

  // A room open to the arm along its whole side.
  double Bay(const Arm& arm, int side, double along, double depth) {
    const double width = FitWidth(arm, along, random_.Uniform(4, 9));
    const RectM room = Beside(arm, side, along, along + width, 0, depth);
    if (!Free(room)) return 0;
    AddZone(ZoneKind::kBay, {room});
    OpenOnArm(arm, side, along, along + width);
    return width;
  }

  // A stair core: a room with a (double) door and the stair's middle wall.
  double Stairs(const Arm& arm, int side, double along, double depth) {
    const double width = std::min(random_.Uniform(3.0, 4.5), arm.Length() - along);
    const RectM room = Beside(arm, side, along, along + width, 0, depth);
    if (width < 3.0 || !Free(room)) return 0;
    AddZone(ZoneKind::kStairs, {room});
    DoorOnArm(arm, side, along, along + width, random_.Uniform(1.0, 1.8), 0.2);
    if (depth >= 4.5) {
      const double middle = along + width / 2;
      layout_.fixtures.push_back(Beside(arm, side, middle - 0.1, middle + 0.1, 1.6, depth - 1.1));
    }
    return width;
  }

  // Two or three lift shafts side by side: closed boxes.
  double Lifts(const Arm& arm, int side, double along, double depth) {
    const int count = random_.Int(2, 3);
    const double shaft = random_.Uniform(1.8, 2.4), shaft_depth = std::min(depth, 2.6);
    if (along + count * shaft > arm.Length()) return 0;
    for (int k = 0; k < count; ++k) {
      if (!Free(Beside(arm, side, along + k * shaft, along + (k + 1) * shaft, 0, shaft_depth))) {
        return 0;
      }
    }
    for (int k = 0; k < count; ++k) {
      layout_.shafts.push_back(
          Beside(arm, side, along + k * shaft, along + (k + 1) * shaft, 0, shaft_depth));
    }
    return count * shaft;
  }

  // A service corridor behind a door, running away from the arm and ending
  // blind, with one or two small rooms on each side.
  double DeadEndBlock(const Arm& arm, int side, double along, double depth) {
    const double room_w = random_.Uniform(2.0, 3.0), branch = random_.Uniform(1.2, 1.6);
    const double width = 2 * room_w + branch;
    if (along + width > arm.Length()) return 0;
    if (!Free(Beside(arm, side, along, along + width, 0, depth))) return 0;
    const double b0 = along + room_w, b1 = b0 + branch;
    AddZone(ZoneKind::kDeadEnd, {Beside(arm, side, b0, b1, 0, depth)});
    DoorOnArm(arm, side, b0, b1, random_.Uniform(0.9, 1.2), 0.1);
    const int rooms = random_.Int(1, 2);
    for (int k = 0; k < rooms; ++k) {
      const double out0 = depth * k / rooms, out1 = depth * (k + 1) / rooms;
      AddZone(ZoneKind::kRoom, {Beside(arm, side, along, b0, out0, out1)});
      DoorAcrossArm(arm, side, b0, out0, out1, random_.Uniform(0.7, 0.9));
      AddZone(ZoneKind::kRoom, {Beside(arm, side, b1, along + width, out0, out1)});
      DoorAcrossArm(arm, side, b1, out0, out1, random_.Uniform(0.7, 0.9));
    }
    return width;
  }

  // A lecture hall below the lobby, its aisle corridor on its right (or
  // left): a stage in front (at the lobby's side), rows of seats split by a
  // middle aisle on wide halls, side aisles, a back aisle; two double doors
  // to the aisle corridor (front and back) and one to the back corridor.
  void Hall(const RectM& hall, bool aisle_on_right) {
    if (!Free(hall)) return;
    AddZone(ZoneKind::kLectureHall, {hall});
    const double stage = random_.Uniform(3, 5), back = 2.4;
    const double side_x = aisle_on_right ? hall.x + hall.width : hall.x;
    AddDoor(hall.y, hall.y + stage, side_x, WallDirection::kVertical, DoubleDoor(), 0.4);
    AddDoor(hall.y + hall.height - back, hall.y + hall.height, side_x, WallDirection::kVertical,
            DoubleDoor(), 0.2);
    AddDoor(hall.x, hall.x + hall.width, hall.y + hall.height, WallDirection::kHorizontal,
            DoubleDoor());
    const double side_aisle = random_.Uniform(1.0, 1.5);
    const double middle_aisle = hall.width >= 16 ? random_.Uniform(1.0, 1.4) : 0;
    const double pitch = random_.Uniform(1.0, 1.25), seat = random_.Uniform(0.45, 0.6);
    const double x0 = hall.x + side_aisle, x1 = hall.x + hall.width - side_aisle;
    for (double y = hall.y + stage; y + seat <= hall.y + hall.height - back; y += pitch) {
      if (middle_aisle > 0) {
        const double mid = 0.5 * (x0 + x1);
        layout_.fixtures.push_back({x0, y, mid - middle_aisle / 2 - x0, seat});
        layout_.fixtures.push_back({mid + middle_aisle / 2, y, x1 - mid - middle_aisle / 2, seat});
      } else {
        layout_.fixtures.push_back({x0, y, x1 - x0, seat});
      }
    }
  }

  // `width`, or the rest of the arm when less than a room would be left.
  double FitWidth(const Arm& arm, double along, double width) const {
    const double rest = arm.Length() - along;
    return rest - width < kMinRowRoomM ? rest : width;
  }

  PortableRandom& random_;
};

}  // namespace

FloorLayout RandomPublicBuildingLayout(PortableRandom& random) {
  PublicBuilder builder(random);
  builder.layout().name = "public building";
  const RectM lobby{0, 0, random.Uniform(16, 30), random.Uniform(18, 30)};
  builder.AddZone(ZoneKind::kLobby, {lobby});
  builder.Pillars(lobby);

  // One narrow and one wide wing, in either order, 100-200 m across.
  const double narrow = random.Uniform(kMinWingCorridorM, 2.2);
  const double wide = random.Uniform(2.6, kMaxWingCorridorM);
  const bool narrow_left = random.Chance(0.5);
  const double across = random.Uniform(100, 200);
  const double left_length = (across - lobby.width) * random.Uniform(0.35, 0.65);
  const double right_length = across - lobby.width - left_length;
  std::vector<std::pair<Arm, double>> wings;  // corridor, its width
  const double left_w = narrow_left ? narrow : wide, right_w = narrow_left ? wide : narrow;
  wings.push_back({builder.WingCorridor(lobby, 0, left_w, left_length), left_w});
  wings.push_back({builder.WingCorridor(lobby, 1, right_w, right_length), right_w});
  builder.LectureBlock(lobby);
  if (random.Chance(0.7)) {
    const double w = random.Uniform(kMinWingCorridorM, kMaxWingCorridorM);
    wings.push_back({builder.WingCorridor(lobby, 2, w, random.Uniform(18, 35)), w});
  }
  double narrowest = kMaxWingCorridorM;
  for (const auto& [arm, width] : wings) {
    narrowest = std::min(narrowest, width);
    for (const int side : {-1, 1}) builder.Row(arm, side, random.Uniform(4, 8), width, false);
  }
  const Arm top{lobby, true}, left{lobby, false};
  for (const int side : {-1, 1}) {
    builder.Row(top, side, random.Uniform(4, 8), lobby.height, true);
    builder.Row(left, side, random.Uniform(4, 8), lobby.width, true);
  }
  FloorLayout layout = std::move(builder.layout());
  layout.corridor_width_m = narrowest;
  FrameLayout(&layout);
  return layout;
}

}  // namespace areagraph::floorplan
