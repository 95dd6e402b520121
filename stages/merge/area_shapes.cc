#include "stages/merge/area_shapes.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>

#include "stages/geometry/corridor_shape.h"
#include "stages/geometry/distance_transform.h"
#include "stages/geometry/edge_polygon.h"
#include "stages/geometry/enclosed_pockets.h"
#include "stages/geometry/region_boxes.h"
#include "stages/merge/furniture_islands.h"

namespace areagraph {
namespace {

// Median and maximum of `widths` (reordered), zeros when empty.
void SetProfile(std::vector<double>* widths, AreaShape* shape) {
  if (widths->empty()) return;
  const auto middle = widths->begin() + widths->size() / 2;
  std::nth_element(widths->begin(), middle, widths->end());
  shape->typical_px = *middle;
  shape->widest_px = *std::max_element(widths->begin(), widths->end());
}

}  // namespace

double AreaShape::Elongation() const { return areagraph::Elongation(typical_px, area_px); }

double AreaShape::Straightness() const { return moments.a > 0 ? moments.Axis().second : 0; }

std::vector<AreaShape> MeasureAreaShapes(const proto::CutGraph& graph, const AreaPlan& plan,
                                         double resolution_m) {
  const std::vector<double> size_m2 = AreaSizesM2(graph, plan, resolution_m);
  const std::vector<AreaMoments> moments = MomentsOfAreas(graph, plan);
  const double cell_m2 = resolution_m * resolution_m;
  std::vector<AreaShape> shapes(plan.areas.size());
  std::vector<double> widths;
  for (size_t k = 0; k < plan.areas.size(); ++k) {
    AreaShape& shape = shapes[k];
    widths.clear();
    double widest_inside = 0;
    for (const int e : plan.areas[k].edges) {
      const proto::GraphEdge& edge = graph.edges(e);
      const double source_reach = graph.vertices(edge.source()).clearance_px();
      const double target_reach = graph.vertices(edge.target()).clearance_px();
      const int n = edge.clearance_px_size();
      // Arc length from the source at each sample (the path's points).
      double arc = 0;
      for (int i = 0; i < n; ++i) {
        if (i > 0 && i < edge.path_size()) {
          arc += (FromProtoPoint(edge.path(i)) - FromProtoPoint(edge.path(i - 1))).norm();
        }
        const double width = 2 * edge.clearance_px(i);
        widths.push_back(width);
        if (arc >= source_reach && edge.length_px() - arc >= target_reach) {
          widest_inside = std::max(widest_inside, width);
        }
      }
    }
    SetProfile(&widths, &shape);
    // Inside the free disk of a vertex the clearance measures that vertex
    // (a junction's disk is wider than the corridors that meet there): the
    // widest is looked for between them, and is the typical width where the
    // edges hold nothing else.
    shape.widest_px = std::max(widest_inside, shape.typical_px);
    shape.area_px = size_m2[k] / cell_m2;
    shape.moments = moments[k];
    shape.corridor =
        IsCorridorShaped(shape.typical_px, shape.widest_px, shape.area_px, resolution_m);
  }
  return shapes;
}

AreaShape RasterShape(const AreaRaster& raster, int k, double resolution_m, double island_max_m,
                      const cv::Mat& furniture) {
  AreaShape shape;
  if (k >= static_cast<int>(raster.boxes.size()) || raster.boxes[k].area() == 0) return shape;
  cv::Mat mask = LabelMaskInBox(raster.labels, k + 1, raster.boxes[k]);
  if (!furniture.empty() && cv::countNonZero(furniture(raster.boxes[k])) > 0) {
    // The mask has a free border of one cell around the box. Only the
    // furniture that touches the area joins it: the box may hold rows of a
    // hall next door.
    const cv::Rect box = raster.boxes[k];
    const cv::Mat own = mask.clone();
    mask(cv::Rect(1, 1, box.width, box.height)).setTo(255, furniture(box) != 0);
    cv::Mat pieces;
    const int count = cv::connectedComponents(mask, pieces, 8, CV_32S);
    std::vector<bool> touches(count, false);
    for (int r = 0; r < own.rows; ++r) {
      for (int c = 0; c < own.cols; ++c) {
        if (own.at<uint8_t>(r, c) != 0) touches[pieces.at<int>(r, c)] = true;
      }
    }
    for (int r = 0; r < mask.rows; ++r) {
      for (int c = 0; c < mask.cols; ++c) {
        if (!touches[pieces.at<int>(r, c)]) mask.at<uint8_t>(r, c) = 0;
      }
    }
  }
  FillEnclosedPockets(island_max_m / resolution_m, &mask);
  const cv::Mat depth = ExactDistanceTransform(mask);
  std::vector<double> widths;
  for (int r = 1; r + 1 < depth.rows; ++r) {
    const float* above = depth.ptr<float>(r - 1);
    const float* row = depth.ptr<float>(r);
    const float* below = depth.ptr<float>(r + 1);
    for (int c = 1; c + 1 < depth.cols; ++c) {
      const float d = row[c];
      if (d > 0 && d >= row[c - 1] && d >= row[c + 1] && d >= above[c] && d >= below[c]) {
        widths.push_back(2.0 * d);
      }
    }
  }
  SetProfile(&widths, &shape);
  shape.area_px = cv::countNonZero(mask);
  shape.corridor = IsCorridorShaped(shape.typical_px, shape.widest_px, shape.area_px, resolution_m);
  return shape;
}

}  // namespace areagraph
