#include "stages/merge/split_corridor_joining.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "stages/geometry/disjoint_sets.h"
#include "stages/geometry/edge_polygon.h"
#include "stages/merge/corridor_labels.h"
#include "stages/merge/vertex_openings.h"

namespace areagraph {
namespace {

// Area, first and second moments of a set of rings, summed over the rings'
// cv::moments (which counts each ring with positive orientation).
struct Moments {
  double a = 0, x = 0, y = 0, xx = 0, yy = 0, xy = 0;

  void AddRing(const google::protobuf::RepeatedPtrField<proto::Point2>& ring) {
    std::vector<cv::Point2f> points;
    points.reserve(ring.size());
    for (const proto::Point2& p : ring) points.emplace_back(p.x(), p.y());
    const cv::Moments m = cv::moments(points);
    a += m.m00, x += m.m10, y += m.m01;
    xx += m.m20, yy += m.m02, xy += m.m11;
  }
  Eigen::Vector2d Centroid() const { return Eigen::Vector2d(x / a, y / a); }
  // The unit direction of the major axis and the ratio of the major to the
  // minor axis' variance (1 for a disk or a square).
  std::pair<Eigen::Vector2d, double> Axis() const {
    const Eigen::Vector2d c = Centroid();
    const double sxx = xx / a - c.x() * c.x();
    const double syy = yy / a - c.y() * c.y();
    const double sxy = xy / a - c.x() * c.y();
    const double mean = (sxx + syy) / 2;
    const double spread = std::sqrt(std::max(0.0, (sxx - syy) * (sxx - syy) / 4 + sxy * sxy));
    const double major = mean + spread, minor = mean - spread;
    const double angle = 0.5 * std::atan2(2 * sxy, sxx - syy);
    return {Eigen::Vector2d(std::cos(angle), std::sin(angle)), minor > 0 ? major / minor : 1e9};
  }
};

}  // namespace

void JoinSplitCorridors(const proto::CutGraph& graph, double resolution_m, bool keep_closed_doors,
                        AreaPlan* plan, const SplitCorridorParams& params) {
  const std::vector<bool> closed = ClosedVertices(graph, keep_closed_doors);
  const double max_width_px = kMaxCorridorWidthM / resolution_m;
  const double cell_m2 = resolution_m * resolution_m;
  const double straight_cos = std::cos(params.straight_deg * M_PI / 180);
  const double axis_cos = std::cos(params.axis_deg * M_PI / 180);
  for (int pass = 0; pass < 8; ++pass) {
    const int area_count = static_cast<int>(plan->areas.size());
    const std::vector<double> size_m2 = AreaSizesM2(graph, *plan, resolution_m);
    std::vector<double> width(area_count);
    for (int k = 0; k < area_count; ++k) width[k] = MedianWidthPx(graph, plan->areas[k]);
    const std::vector<std::map<int, VertexOpening>> openings = OpeningsAtVertices(graph, *plan);
    std::vector<Moments> moments(area_count);
    for (int e = 0; e < graph.edges_size(); ++e) {
      moments[plan->area_of_edge[e]].AddRing(graph.edges(e).polygon().outer().points());
    }
    DisjointSets groups(area_count);
    bool changed = false;
    for (int vertex = 0; vertex < graph.vertices_size(); ++vertex) {
      if (closed[vertex]) continue;
      const std::map<int, VertexOpening>& at = openings[vertex];
      for (auto a = at.begin(); a != at.end(); ++a) {
        for (auto b = std::next(a); b != at.end(); ++b) {
          const int i = a->first, j = b->first;
          const double narrow = std::min(width[i], width[j]);
          const double wide = std::max(width[i], width[j]);
          if (narrow <= 0 || wide > max_width_px || wide > params.width_ratio * narrow) continue;
          if (narrow < params.min_width_m / resolution_m) continue;
          const double opening = std::min(a->second.width_px, b->second.width_px);
          if (opening < params.opening_share * wide) continue;
          const double union_px = (size_m2[i] + size_m2[j]) / cell_m2;
          if (union_px < params.elongation * wide * wide) continue;
          if (moments[i].a <= 0 || moments[j].a <= 0) continue;
          const Eigen::Vector2d vertex_at = FromProtoPoint(graph.vertices(vertex).position());
          const Eigen::Vector2d ci = moments[i].Centroid(), cj = moments[j].Centroid();
          const double across = (ci - vertex_at).normalized().dot((cj - vertex_at).normalized());
          if (across > straight_cos) continue;
          bool aligned = true;
          const Eigen::Vector2d line = (cj - ci).normalized();
          for (const int k : {i, j}) {
            const auto [axis, ratio] = moments[k].Axis();
            if (ratio >= params.axis_ratio && std::abs(axis.dot(line)) < axis_cos) aligned = false;
          }
          if (!aligned) continue;
          if (groups.Union(i, j)) changed = true;
        }
      }
    }
    if (!changed) break;
    std::vector<int> root(area_count);
    for (int k = 0; k < area_count; ++k) root[k] = groups.Find(k);
    plan->MergeGroups(root);
  }
}

}  // namespace areagraph
