#include "stages/cut/room_disks.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "stages/cut/cut_passes.h"
#include "stages/cut/width_estimate.h"

namespace areagraph {

double SmallRoomWidthM(const proto::CutOptions& options, const proto::RoomWidthEstimate& estimate,
                       double robot_width_m) {
  if (!estimate.automatic() || estimate.doors_size() == 0) return 0;
  if (!RunsCutPass(options, proto::CutOptions::SMALL_ROOM_DISK)) return 0;
  // The estimate's doors are widest first.
  const double typical_door = estimate.doors(estimate.doors_size() / 2).width_m();
  return std::max(typical_door + kPaperWidthMarginM, MinRoomWidthM(robot_width_m));
}

int DropSmallRooms(double width_px, int room_count, SiteAlphaShape* shape) {
  // A room must at least hold the disk; smaller ones are slivers where a
  // corridor about the disk's width bulges a little.
  const double min_area = M_PI * width_px * width_px / 4;
  const std::vector<double> areas = shape->RoomAreas();
  std::vector<int> renumber(room_count, -1);
  int kept = 0;
  for (int room = 0; room < room_count; ++room) {
    if (room < static_cast<int>(areas.size()) && areas[room] >= min_area) renumber[room] = kept++;
  }
  shape->RenumberRooms(renumber);
  return kept;
}

RoomDisks::RoomDisks(PointList&& sites, double room_width_px, double small_width_px,
                     const std::function<bool(const Eigen::Vector2d&)>& inside_boundary,
                     const proto::TopologyGraph& topology) {
  const bool small_disk = small_width_px > 0 && small_width_px < room_width_px;
  SiteTriangulationPtr triangulation = TriangulateSites(std::move(sites));
  // Each shape labels the faces: the small disk's takes a copy, cheaper
  // than triangulating the sites again.
  SiteTriangulationPtr copy = small_disk ? CopySiteTriangulation(*triangulation) : nullptr;
  big_ = std::make_unique<SiteAlphaShape>(std::move(triangulation), room_width_px / 2);
  room_count_ = DropSmallRooms(room_width_px, big_->DetectRooms(inside_boundary), big_.get());
  if (!small_disk) return;
  small_ = std::make_unique<SiteAlphaShape>(std::move(copy), small_width_px / 2);
  const int small_count =
      DropSmallRooms(small_width_px, small_->DetectRooms(inside_boundary), small_.get());
  // The graph runs through every room, and a room of the big disk lies in
  // one room of the small disk: one point of it answers for the room.
  std::vector<bool> holds_big(small_count, false);
  std::vector<bool> placed(room_count_, false);
  for (const proto::GraphEdge& edge : topology.edges()) {
    for (const proto::Point2& point : edge.path()) {
      const Eigen::Vector2d p(point.x(), point.y());
      const int big = big_->RoomAt(p);
      if (big < 0 || placed[big]) continue;
      placed[big] = true;
      const int small = small_->RoomAt(p);
      if (small >= 0) holds_big[small] = true;
    }
  }
  // The small disk's rooms take ids after the big disk's; -1 for those
  // holding a big room, where the big disk decides.
  std::vector<int> ids(small_count, -1);
  for (int room = 0; room < small_count; ++room) {
    if (!holds_big[room]) ids[room] = room_count_++;
  }
  small_->RenumberRooms(ids);
}

RoomDisks::~RoomDisks() = default;

int RoomDisks::RoomAt(const Eigen::Vector2d& point) {
  const int big = big_->RoomAt(point);
  return big >= 0 || small_ == nullptr ? big : small_->RoomAt(point);
}

void RoomDisks::RenumberRooms(const std::vector<int>& new_ids) {
  big_->RenumberRooms(new_ids);
  if (small_ != nullptr) small_->RenumberRooms(new_ids);
}

std::vector<proto::Polygon> RoomDisks::RoomOutlines() {
  std::vector<proto::Polygon> outlines = big_->RoomOutlines();
  if (small_ == nullptr) return outlines;
  std::vector<proto::Polygon> small = small_->RoomOutlines();
  if (small.size() > outlines.size()) outlines.resize(small.size());
  for (size_t room = 0; room < small.size(); ++room) {
    if (small[room].outer().points_size() > 0) outlines[room] = std::move(small[room]);
  }
  return outlines;
}

}  // namespace areagraph
