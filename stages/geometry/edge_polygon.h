#pragma once

#include <google/protobuf/repeated_field.h>

#include <Eigen/Core>
#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/geometry/ring_points.h"

namespace areagraph {

PointList ToPointList(const google::protobuf::RepeatedPtrField<proto::Point2>& points);
void AppendPoints(const PointList& points, google::protobuf::RepeatedPtrField<proto::Point2>* out);
proto::Point2 ToProtoPoint(const Eigen::Vector2d& point);
Eigen::Vector2d FromProtoPoint(const proto::Point2& point);

// The half-polygon of a Topology Graph edge on one side (the paper's
// hpoly(h)): the path forward, then the sites of that side backward, so that
// it is the union of the Voronoi faces' slices between the path and the wall.
// `sites[i]` belongs to path segment i. Consecutive duplicates are dropped.
proto::Ring HalfPolygonRing(const PointList& path, const PointList& sites);

// The whole polygon of an edge, the union of its two halves: path[0], the
// right sites forward, path[last], the left sites backward.
proto::Ring EdgePolygonRing(const PointList& path, const PointList& left_sites,
                            const PointList& right_sites);

// Sets left_half, right_half and polygon of `edge` from its path and sites.
void UpdateEdgePolygons(proto::GraphEdge* edge);

// Polyline length of `path`.
double PathLength(const PointList& path);

}  // namespace areagraph
