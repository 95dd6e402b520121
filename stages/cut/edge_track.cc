#include "stages/cut/edge_track.h"

#include <algorithm>

#include "common/error.h"

namespace areagraph {
namespace {

constexpr double kSamePointPx = 1e-9;

}  // namespace

EdgeTrack::EdgeTrack(const proto::GraphEdge& edge)
    : edge_(&edge),
      path_(ToPointList(edge.path())),
      left_sites_(ToPointList(edge.left_sites())),
      right_sites_(ToPointList(edge.right_sites())) {
  const size_t segments = path_.size() < 2 ? 0 : path_.size() - 1;
  if (segments == 0 || left_sites_.size() != segments || right_sites_.size() != segments ||
      static_cast<size_t>(edge.clearance_px_size()) != path_.size()) {
    throw InputError("the Topology Graph artifact is corrupt: edge " + std::to_string(edge.id()) +
                     " has " + std::to_string(path_.size()) + " path points, " +
                     std::to_string(left_sites_.size()) + "/" +
                     std::to_string(right_sites_.size()) + " sites and " +
                     std::to_string(edge.clearance_px_size()) + " clearances");
  }
  arc_.resize(path_.size(), 0.0);
  for (size_t i = 1; i < path_.size(); ++i)
    arc_[i] = arc_[i - 1] + (path_[i] - path_[i - 1]).norm();
}

PathPosition EdgeTrack::AtVertex(int index) const {
  if (index >= segment_count()) return End();
  return {index, 0};
}

PathPosition EdgeTrack::Normalized(PathPosition position) const {
  position.segment = std::clamp(position.segment, 0, segment_count() - 1);
  position.t = std::clamp(position.t, 0.0, 1.0);
  if (position.t >= 1 - 1e-12 && position.segment + 1 < segment_count()) {
    return {position.segment + 1, 0};
  }
  return position;
}

Eigen::Vector2d EdgeTrack::PointAt(const PathPosition& position) const {
  const Eigen::Vector2d& a = path_[position.segment];
  const Eigen::Vector2d& b = path_[position.segment + 1];
  return a + position.t * (b - a);
}

double EdgeTrack::ArcAt(const PathPosition& position) const {
  return arc_[position.segment] +
         position.t * (arc_[position.segment + 1] - arc_[position.segment]);
}

double EdgeTrack::ClearanceAt(const PathPosition& position) const {
  if (position.t <= 0) return edge_->clearance_px(position.segment);
  if (position.t >= 1) return edge_->clearance_px(position.segment + 1);
  return (PointAt(position) - left_sites_[position.segment]).norm();
}

proto::GraphEdge EdgeTrack::Piece(const PathPosition& begin, const PathPosition& end) const {
  PointList path{PointAt(begin)};
  PointList left, right;
  std::vector<double> clearance{ClearanceAt(begin)};
  auto add = [&](const Eigen::Vector2d& point, double point_clearance, int segment) {
    if ((point - path.back()).norm() <= kSamePointPx && path.size() > 1) return;
    path.push_back(point);
    clearance.push_back(point_clearance);
    left.push_back(left_sites_[segment]);
    right.push_back(right_sites_[segment]);
  };
  for (int segment = begin.segment; segment < end.segment; ++segment) {
    add(path_[segment + 1], edge_->clearance_px(segment + 1), segment);
  }
  add(PointAt(end), ClearanceAt(end), end.segment);

  proto::GraphEdge piece;
  AppendPoints(path, piece.mutable_path());
  AppendPoints(left, piece.mutable_left_sites());
  AppendPoints(right, piece.mutable_right_sites());
  for (double c : clearance) piece.add_clearance_px(c);
  piece.set_length_px(PathLength(path));
  piece.set_min_clearance_px(*std::min_element(clearance.begin(), clearance.end()));
  UpdateEdgePolygons(&piece);
  return piece;
}

}  // namespace areagraph
