#pragma once

#include <optional>
#include <vector>

#include "proto/pipeline_options.pb.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {

// A point on a drawn floor, in plan metres (x right, y down from the
// top-left corner, like floorplan::RectM).
struct PlanPoint {
  double x_m = 0;
  double y_m = 0;
};

// A drawn floor on which one merge pass has an effect that shows in the
// areas: with the pass, the area at `probe` is (`joined` true) or is not
// (`joined` false) the area at one of `partners`; with the pass skipped it is
// the other way round.
struct MergePassCase {
  const char* what;
  floorplan::FloorPlan floor;
  proto::PipelineOptions options;
  PlanPoint probe;
  std::vector<PlanPoint> partners;
  bool joined = true;
};

// The case of `pass`, or none for a pass that has no case yet.
std::optional<MergePassCase> CaseOfMergePass(proto::MergeOptions::Pass pass);

// Options with a fixed W of `room_width_m` (a number for cut.room_width_m
// skips the estimate).
proto::PipelineOptions FixedRoomWidth(double room_width_m);

// The floors of the cases that other tests look at more closely.

// A 5 x 4 m room above a 1.8 m corridor, joined by a 0.9 m door at x = 2 m;
// a 4 x 4 m office beside it with its own 0.9 m door. Down the middle of the
// room (x = 3.5 m) stands `divider`.
floorplan::FloorPlan RoomWithDivider(const floorplan::RectM& divider);
// A cabinet 0.6 m deep and 2.45 m long across RoomWithDivider's room,
// leaving 0.7 m to the walls above and below it: narrower than W (about 1 m,
// above the doors), too long and thin for ag-cut's furniture islands
// (cut.islands.max_length_m allows 3 times as long as wide).
inline constexpr floorplan::RectM kCabinetAcrossRoom{3.2, 1.8, 0.6, 2.45};

// A 6 x 4 m room with a bay about 0.95 m wide and 2.5 m deep on its lower
// wall, open to the room over its whole width.
floorplan::FloorPlan RoomWithOpenBay();

// Offices 4 m deep from x = 0.5 m along `length_m`, `office_m` wide, each with
// a 0.9 m door in the wall at y = `corridor_y_m` below them.
void DrawOffices(floorplan::FloorPlan& plan, double length_m, double office_m, double corridor_y_m);

// A corridor 30 x 2.2 m at y = 4.5 m (2.05 m between its walls) under six
// offices; two wall stubs 0.3 m long, reaching 0.175 m out of the walls, face
// each other across the corridor at x = 15.5 m.
floorplan::FloorPlan CorridorWithStubs();

// A corridor 20 x 2.2 m at y = 4.5 m under four offices, with a dead-end
// branch 1.05 m wide and 6 m long down from x = 7 m, open across its whole
// width, and a closet 1.2 m wide and 4.5 m deep behind a 0.7 m door at
// x = 15.6 m.
floorplan::FloorPlan CorridorWithStem();

// A 6 x 5 m room {0.5, 0.5, 6, 5} and a closet {6.5, 0.5, 1.2, 1.5} beside
// its top right corner, with a 0.8 m door in the wall between them. With
// `far_wall_unknown` the closet's far wall was never seen: unknown cells.
floorplan::FloorPlan RoomAndCloset(bool far_wall_unknown = false);

// A 12 x 12 m lecture hall {1, 1, 12, 12} above a 2 m corridor {1, 13, 16, 2},
// joined by a 1.2 m door; a 4 x 4 m office {13, 1, 4, 4} beside the hall with
// 0.9 m doors to both. `rows` rows of seats 0.5 m deep and 9.6 m long stand
// 1.1 m apart from y = 4 m on (kFirstSeatRowY, kSeatRowPitch), with 1.2 m side
// aisles.
floorplan::FloorPlan HallWithSeatRows(int rows);
inline constexpr double kFirstSeatRowY = 4;
inline constexpr double kSeatRowPitch = 1.1;

}  // namespace areagraph::testing
