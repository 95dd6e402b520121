#include "stages/geometry/edge_polygon.h"

namespace areagraph {
namespace {

// Appends `point` unless it repeats the ring's last point.
void PushDistinct(const Eigen::Vector2d& point, PointList* ring) {
  if (ring->empty() || (ring->back() - point).squaredNorm() > 1e-18) ring->push_back(point);
}

proto::Ring ToRing(PointList ring) {
  while (ring.size() > 1 && (ring.back() - ring.front()).squaredNorm() <= 1e-18) ring.pop_back();
  proto::Ring out;
  SetPackedRing(ring, &out);
  return out;
}

}  // namespace

PointList ToPointList(const google::protobuf::RepeatedPtrField<proto::Point2>& points) {
  PointList out;
  out.reserve(points.size());
  for (const proto::Point2& point : points) out.push_back(FromProtoPoint(point));
  return out;
}

void AppendPoints(const PointList& points, google::protobuf::RepeatedPtrField<proto::Point2>* out) {
  out->Reserve(out->size() + static_cast<int>(points.size()));
  for (const Eigen::Vector2d& point : points) *out->Add() = ToProtoPoint(point);
}

proto::Point2 ToProtoPoint(const Eigen::Vector2d& point) {
  proto::Point2 out;
  out.set_x(point.x());
  out.set_y(point.y());
  return out;
}

Eigen::Vector2d FromProtoPoint(const proto::Point2& point) { return {point.x(), point.y()}; }

proto::Ring HalfPolygonRing(const PointList& path, const PointList& sites) {
  PointList ring;
  for (const Eigen::Vector2d& point : path) PushDistinct(point, &ring);
  for (auto it = sites.rbegin(); it != sites.rend(); ++it) PushDistinct(*it, &ring);
  return ToRing(std::move(ring));
}

proto::Ring EdgePolygonRing(const PointList& path, const PointList& left_sites,
                            const PointList& right_sites) {
  PointList ring;
  if (path.empty()) return proto::Ring();
  PushDistinct(path.front(), &ring);
  for (const Eigen::Vector2d& site : right_sites) PushDistinct(site, &ring);
  PushDistinct(path.back(), &ring);
  for (auto it = left_sites.rbegin(); it != left_sites.rend(); ++it) PushDistinct(*it, &ring);
  return ToRing(std::move(ring));
}

void UpdateEdgePolygons(proto::GraphEdge* edge) {
  const PointList path = ToPointList(edge->path());
  const PointList left = ToPointList(edge->left_sites());
  const PointList right = ToPointList(edge->right_sites());
  *edge->mutable_left_half()->mutable_outer() = HalfPolygonRing(path, left);
  *edge->mutable_right_half()->mutable_outer() = HalfPolygonRing(path, right);
  *edge->mutable_polygon()->mutable_outer() = EdgePolygonRing(path, left, right);
}

double PathLength(const PointList& path) {
  double length = 0;
  for (size_t i = 1; i < path.size(); ++i) length += (path[i] - path[i - 1]).norm();
  return length;
}

}  // namespace areagraph
