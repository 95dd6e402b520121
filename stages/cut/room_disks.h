#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "proto/artifacts.pb.h"
#include "proto/pipeline_options.pb.h"
#include "stages/geometry/edge_polygon.h"
#include "stages/geometry/site_alpha_shape.h"

namespace areagraph {

// The rooms of the room disk (diameter W), and, for an automatic W, the
// rooms of a smaller disk where the big one holds no room at all.
//
// An automatic W stays above the building's widest doors, so that no disk
// passes a door; in a building with double doors that W is wider than the
// free width inside its small rooms (a furnished office, a store room), and
// the room disk finds no room there or only a corner of one: the rest is
// cut into pieces along the graph. The small disk (`small_width_px`, the W
// of the building's typical door) decides locally: a space that the small
// disk holds as one room, in which the big disk finds no room, is one room.
// Where the small disk's room holds a room of the big disk, the big disk
// decides, as before: the small disk passes the double doors, which the
// big one is there to stop.
//
// With `small_width_px` at or above W, the rooms are the room disk's alone.
class RoomDisks {
 public:
  RoomDisks(PointList&& sites, double room_width_px, double small_width_px,
            const std::function<bool(const Eigen::Vector2d&)>& inside_boundary,
            const proto::TopologyGraph& topology);
  ~RoomDisks();

  // Rooms found (before any renumbering).
  int room_count() const { return room_count_; }
  // The room containing `point`, or -1.
  int RoomAt(const Eigen::Vector2d& point);
  // Room r becomes new_ids[r] (-1 drops it).
  void RenumberRooms(const std::vector<int>& new_ids);
  // Outline of every room, indexed by room id.
  std::vector<proto::Polygon> RoomOutlines();

 private:
  std::unique_ptr<SiteAlphaShape> big_;
  std::unique_ptr<SiteAlphaShape> small_;
  // Rooms of the big disk first, then those of the small one.
  int room_count_ = 0;
};

// The small disk's width (metres): the W of the building's typical door,
// its median door + kPaperWidthMarginM, as an estimated W is its widest
// door + the margin. 0 (no small disk) for a fixed W, a map without doors
// or with cut pass SMALL_ROOM_DISK skipped; never below the least W for a
// body `robot_width_m` wide (MinRoomWidthM).
double SmallRoomWidthM(const proto::CutOptions& options, const proto::RoomWidthEstimate& estimate,
                       double robot_width_m);

// Drops the rooms too small to hold the disk of diameter `width_px`; returns
// the number kept.
int DropSmallRooms(double width_px, int room_count, SiteAlphaShape* shape);

}  // namespace areagraph
