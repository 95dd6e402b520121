#pragma once

#include <array>
#include <opencv2/core.hpp>
#include <utility>
#include <vector>

#include "proto/geometry.pb.h"

namespace areagraph {

// The greys a map's cells are drawn in: free, occupied, and unknown (also
// any other state).
inline constexpr uint8_t kFreeCellGrey = 255, kOccupiedCellGrey = 40, kUnknownCellGrey = 200;

// A picture of a map, upscaled so that thin lines and labels stay readable,
// with drawing helpers that take pixel coordinates of the map.
class Canvas {
 public:
  // `cells` are CellState bytes (free white, occupied black, unknown grey).
  Canvas(const std::string& cells, int width, int height, int scale);

  int scale() const { return scale_; }
  // The BGR picture, made from the map's greys on first use.
  cv::Mat& image();
  // The map's greys (CV_8UC1) while nothing has been drawn (image() was never
  // called), else an empty Mat: a bare map is written from its greys
  // (WriteGreyPngFileAsColour), the same file without a BGR picture.
  cv::Mat UntouchedGrey() const { return image_.empty() ? grey_ : cv::Mat(); }

  cv::Point ToCanvas(const proto::Point2& point) const;
  // The same for a point held as two numbers (a Voronoi vertex).
  cv::Point ToCanvas(const cv::Point2d& point) const;
  void Line(const proto::Point2& a, const proto::Point2& b, const cv::Scalar& colour,
            int thickness);
  void Line(const cv::Point2d& a, const cv::Point2d& b, const cv::Scalar& colour, int thickness);
  void Dot(const proto::Point2& at, const cv::Scalar& colour, int radius);
  void Outline(const proto::Ring& ring, const cv::Scalar& colour, int thickness);
  // Fills a polygon (outer minus holes) blending `colour` with weight `alpha`.
  void Fill(const proto::Polygon& polygon, const cv::Scalar& colour, double alpha);
  // Line for each pair of points, in their order, through one OpenCV call:
  // the same pixels, without cv::line's per-call cost (a Voronoi diagram has
  // tens of thousands of edges).
  void Lines(const std::vector<std::pair<cv::Point2d, cv::Point2d>>& lines,
             const cv::Scalar& colour, int thickness);
  // Blends `colour` with weight `alpha` into the pixels of 1-px lines (pairs
  // of points), each pixel once: faint lines through which the map shows.
  void FaintLines(const std::vector<std::pair<cv::Point2d, cv::Point2d>>& lines,
                  const cv::Scalar& colour, double alpha);
  void Label(const proto::Point2& at, const std::string& text, const cv::Scalar& colour);
  // Paints whole map cells (flat indices), e.g. removed obstacles.
  void PaintCells(const google::protobuf::RepeatedField<int32_t>& cells, int width,
                  const cv::Scalar& colour);

 private:
  int scale_;
  cv::Mat grey_;  // until image() makes the BGR picture from it
  cv::Mat image_;
};

// `grey` (CV_8UC1) with every pixel repeated `scale` times in both
// directions: the picture cv::resize makes with INTER_NEAREST, in less than
// half of its instructions.
cv::Mat UpscaleNearest(const cv::Mat& grey, int scale);

// For each BGR channel, what blending `colour` with weight `alpha` makes of
// each 8-bit value, computed as cv::addWeighted(picture, 1 - alpha, colour,
// alpha, 0) does: in float, rounded to the nearest. The same values for
// alpha 0.5 (every product and sum exact; a test holds them to it), within
// one for others, where OpenCV's vector code may fuse the multiply-add.
using BlendTables = std::array<std::array<uint8_t, 256>, 3>;
BlendTables BlendTablesFor(const cv::Scalar& colour, double alpha);

// Distinct, well separated colours for ids (golden-angle hues).
cv::Scalar DistinctColour(int id);

// The most pixels per cell (at most 8) that keep the longer side within
// 1000 px, and 1 for maps bigger than that: a picture about the map's own
// size, like the docs' pictures. (It aimed at 1600 px, which drew lab_a at
// 2 x and made encoding four times the pixels cost more than some stages.)
int DefaultScale(int width, int height);

}  // namespace areagraph
