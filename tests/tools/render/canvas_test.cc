// The canvas under every picture: the map's cells at the chosen scale, and
// lines drawn with their exact colour (not anti-aliased).
#include "tools/render/canvas.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <set>
#include <string>
#include <utility>

#include "proto/artifacts.pb.h"
#include "tools/render/artifact_drawing.h"

namespace areagraph {
namespace {

proto::Point2 At(double x, double y) {
  proto::Point2 point;
  point.set_x(x);
  point.set_y(y);
  return point;
}

// The canvas upscales with its own loop (half of cv::resize's work): it must
// give OpenCV's picture byte for byte.
TEST(Canvas, UpscaleNearestIsCvResizeNearestAtEveryScale) {
  cv::Mat grey(37, 53, CV_8UC1);
  cv::randu(grey, 0, 256);
  for (int scale = 1; scale <= 16; ++scale) {
    cv::Mat expected;
    cv::resize(grey, expected, cv::Size(grey.cols * scale, grey.rows * scale), 0, 0,
               cv::INTER_NEAREST);
    const cv::Mat upscaled = UpscaleNearest(grey, scale);
    ASSERT_EQ(upscaled.size(), expected.size()) << scale;
    EXPECT_EQ(cv::norm(upscaled, expected, cv::NORM_INF), 0) << "scale " << scale;
  }
}

TEST(Canvas, ColourPictureIsCvtColorOfTheGreysAndShortCellsAreUnknown) {
  std::string cells(30, static_cast<char>(proto::CELL_FREE));
  for (size_t i = 0; i < cells.size(); i += 3) cells[i] = static_cast<char>(proto::CELL_OCCUPIED);
  Canvas canvas(cells, 7, 5, 2);  // 35 cells, 30 given
  const cv::Mat grey = canvas.UntouchedGrey().clone();
  ASSERT_EQ(grey.size(), cv::Size(14, 10));
  EXPECT_EQ(grey.at<uint8_t>(9, 13), 200);  // cell 34: missing, so unknown
  EXPECT_EQ(grey.at<uint8_t>(0, 0), 40);
  EXPECT_EQ(grey.at<uint8_t>(0, 2), 255);
  cv::Mat expected;
  cv::cvtColor(grey, expected, cv::COLOR_GRAY2BGR);
  EXPECT_EQ(cv::norm(canvas.image(), expected, cv::NORM_INF), 0);
  EXPECT_TRUE(canvas.UntouchedGrey().empty());
}

TEST(Canvas, DrawsEachCellAsScaleByScalePixelsOfItsStateColour) {
  // 3 x 2 cells: free, occupied, unknown / unknown, free, occupied.
  const std::string cells = {proto::CELL_FREE,    proto::CELL_OCCUPIED, proto::CELL_UNKNOWN,
                             proto::CELL_UNKNOWN, proto::CELL_FREE,     proto::CELL_OCCUPIED};
  for (const int scale : {1, 3}) {
    Canvas canvas(cells, 3, 2, scale);
    ASSERT_EQ(canvas.image().size(), cv::Size(3 * scale, 2 * scale));
    ASSERT_EQ(canvas.image().type(), CV_8UC3);
    const cv::Vec3b free(255, 255, 255), occupied(40, 40, 40), unknown(200, 200, 200);
    const cv::Vec3b expected[2][3] = {{free, occupied, unknown}, {unknown, free, occupied}};
    for (int y = 0; y < 2 * scale; ++y) {
      for (int x = 0; x < 3 * scale; ++x) {
        EXPECT_EQ(canvas.image().at<cv::Vec3b>(y, x), expected[y / scale][x / scale])
            << "scale " << scale << " at " << x << "," << y;
      }
    }
  }
}

TEST(Canvas, AShortCellStringLeavesTheRestUnknown) {
  Canvas canvas(std::string(1, static_cast<char>(proto::CELL_FREE)), 2, 1, 1);
  EXPECT_EQ(canvas.image().at<cv::Vec3b>(0, 0), cv::Vec3b(255, 255, 255));
  EXPECT_EQ(canvas.image().at<cv::Vec3b>(0, 1), cv::Vec3b(200, 200, 200));
}

// PaintCells writes the pixel blocks itself: the same picture as one
// filled cv::rectangle per cell, and cells past the map (a damaged artifact)
// are clipped away as cv::rectangle clips them.
TEST(Canvas, PaintCellsIsAFilledRectanglePerCell) {
  const int width = 9, height = 7;
  google::protobuf::RepeatedField<int32_t> cells;
  for (const int32_t cell : {0, 8, 10, 31, 62, 62, 63, 70, -1, 1 << 30}) cells.Add(cell);
  const cv::Scalar colour(10, 200.4, 77.6);
  for (const int scale : {1, 2, 5}) {
    Canvas canvas(std::string(width * height, static_cast<char>(proto::CELL_FREE)), width, height,
                  scale);
    cv::Mat expected = canvas.image().clone();
    for (const int32_t cell : cells) {
      if (cell < 0 || cell >= width * height) continue;
      cv::rectangle(expected,
                    cv::Rect((cell % width) * scale, (cell / width) * scale, scale, scale), colour,
                    cv::FILLED);
    }
    canvas.PaintCells(cells, width, colour);
    EXPECT_EQ(cv::norm(canvas.image(), expected, cv::NORM_INF), 0) << "scale " << scale;
    EXPECT_EQ(canvas.image().at<cv::Vec3b>(0, 0), cv::Vec3b(10, 200, 78));
  }
}

TEST(Canvas, VoronoiEdgesAreDrawnInTheirExactColours) {
  proto::VoronoiDiagram voronoi;
  for (const auto& [x, y] : {std::pair{2, 10}, {38, 10}, {2, 15}, {38, 15}}) {
    *voronoi.add_vertices()->mutable_position() = At(x, y);
  }
  proto::VoronoiEdge* skeleton = voronoi.add_edges();
  skeleton->set_source(0);
  skeleton->set_target(1);
  skeleton->set_clearance_px(8);  // the widest edge: pure blue, 2 px
  proto::VoronoiEdge* hugging = voronoi.add_edges();
  hugging->set_source(2);
  hugging->set_target(3);
  hugging->set_clearance_px(1);  // near an obstacle: faint, blended half into the map
  Canvas canvas(std::string(40 * 20, static_cast<char>(proto::CELL_FREE)), 40, 20, 2);
  DrawVoronoiDiagram(voronoi, canvas);
  const cv::Vec3b blue(255, 60, 0), faint(225, 215, 250), white(255, 255, 255);
  for (int x = 8; x < 72; x += 4) {
    EXPECT_EQ(canvas.image().at<cv::Vec3b>(20, x), blue) << x;
    EXPECT_EQ(canvas.image().at<cv::Vec3b>(30, x), faint) << x;
  }
  EXPECT_EQ(canvas.image().at<cv::Vec3b>(10, 40), white);
  EXPECT_EQ(canvas.image().at<cv::Vec3b>(20, 78), white);  // beyond the edge's end
  // Not anti-aliased: the picture has these three colours only.
  std::set<int> colours;
  for (auto it = canvas.image().begin<cv::Vec3b>(); it != canvas.image().end<cv::Vec3b>(); ++it) {
    colours.insert((*it)[0] | (*it)[1] << 8 | (*it)[2] << 16);
  }
  EXPECT_EQ(colours.size(), 3u);

  // The same diagram as format 2 (packed arrays, voronoi 3) draws the same
  // picture; the test above drew format 1, as older stores hold it.
  proto::VoronoiDiagram packed;
  for (const proto::VoronoiVertex& vertex : voronoi.vertices()) {
    packed.add_vertex_x(vertex.position().x());
    packed.add_vertex_y(vertex.position().y());
    packed.add_vertex_clearance_px(1);
  }
  for (const proto::VoronoiEdge& edge : voronoi.edges()) {
    packed.add_edge_source(edge.source());
    packed.add_edge_target(edge.target());
    packed.add_edge_left_site(0);
    packed.add_edge_right_site(0);
    packed.add_edge_clearance_px(edge.clearance_px());
  }
  Canvas packed_canvas(std::string(40 * 20, static_cast<char>(proto::CELL_FREE)), 40, 20, 2);
  DrawVoronoiDiagram(packed, packed_canvas);
  EXPECT_EQ(cv::norm(packed_canvas.image(), canvas.image(), cv::NORM_INF), 0);
}

// Lines (one cv::polylines call for many segments) draws what a cv::line per
// segment draws, in order: overlapping segments of other colours, thick
// lines with their round ends, and fractional end points.
TEST(Canvas, LinesDrawWhatALinePerSegmentDraws) {
  cv::RNG random(7);
  std::vector<std::pair<cv::Point2d, cv::Point2d>> segments;
  for (int i = 0; i < 200; ++i) {
    segments.emplace_back(cv::Point2d(random.uniform(-2.0, 42.0), random.uniform(-2.0, 22.0)),
                          cv::Point2d(random.uniform(-2.0, 42.0), random.uniform(-2.0, 22.0)));
  }
  const std::string cells(40 * 20, static_cast<char>(proto::CELL_FREE));
  for (const int thickness : {1, 2, 3}) {
    Canvas batched(cells, 40, 20, 2), single(cells, 40, 20, 2);
    for (size_t start = 0; start < segments.size(); start += 50) {
      const cv::Scalar colour = DistinctColour(static_cast<int>(start));
      const std::vector<std::pair<cv::Point2d, cv::Point2d>> run(segments.begin() + start,
                                                                 segments.begin() + start + 50);
      batched.Lines(run, colour, thickness);
      for (const auto& [a, b] : run) single.Line(a, b, colour, thickness);
    }
    EXPECT_EQ(cv::norm(batched.image(), single.image(), cv::NORM_INF), 0) << thickness;
    EXPECT_GT(cv::countNonZero(batched.image().reshape(1) != 255), 0);
  }
}

// The blend tables give what cv::addWeighted gives at FaintLines' alpha, for
// every value of a channel against every value of the colour (a picture
// long enough for OpenCV's vector code).
TEST(Canvas, BlendTablesAreAddWeightedAtOneHalf) {
  cv::Mat values(256, 256, CV_8UC3);
  for (int colour = 0; colour < 256; ++colour) {
    for (int v = 0; v < 256; ++v) values.at<cv::Vec3b>(colour, v) = cv::Vec3b(v, 255 - v, v ^ 85);
  }
  for (int colour = 0; colour < 256; ++colour) {
    const cv::Scalar tint(colour, (colour * 7) % 256, 255 - colour);
    const cv::Mat row = values.row(colour);
    cv::Mat expected;
    cv::addWeighted(row, 0.5, cv::Mat(row.size(), row.type(), tint), 0.5, 0, expected);
    const BlendTables tables = BlendTablesFor(tint, 0.5);
    for (int v = 0; v < 256; ++v) {
      const cv::Vec3b in = row.at<cv::Vec3b>(0, v), out = expected.at<cv::Vec3b>(0, v);
      for (int c = 0; c < 3; ++c) {
        ASSERT_EQ(tables[c][in[c]], out[c]) << "colour " << colour << " value " << int(in[c]);
      }
    }
  }
}

// FaintLines blends exactly the pixels of its 1-px lines, each once, as the
// whole-picture cv::addWeighted and a masked copy did before.
TEST(Canvas, FaintLinesBlendWhatAddWeightedUnderAMaskBlended) {
  cv::RNG random(11);
  std::vector<std::pair<cv::Point2d, cv::Point2d>> segments;
  for (int i = 0; i < 300; ++i) {
    segments.emplace_back(cv::Point2d(random.uniform(-2.0, 62.0), random.uniform(-2.0, 42.0)),
                          cv::Point2d(random.uniform(-2.0, 62.0), random.uniform(-2.0, 42.0)));
  }
  std::string cells(60 * 40, static_cast<char>(proto::CELL_FREE));
  for (size_t i = 0; i < cells.size(); i += 7) cells[i] = static_cast<char>(proto::CELL_OCCUPIED);
  for (size_t i = 3; i < cells.size(); i += 11) cells[i] = static_cast<char>(proto::CELL_UNKNOWN);
  const cv::Scalar colour(195, 175, 245);
  for (const int scale : {1, 3}) {
    Canvas canvas(cells, 60, 40, scale), reference(cells, 60, 40, scale);
    canvas.Line(At(1, 1), At(50, 30), cv::Scalar(10, 200, 30), 2);  // colours under the lines
    reference.Line(At(1, 1), At(50, 30), cv::Scalar(10, 200, 30), 2);
    canvas.FaintLines(segments, colour, 0.5);
    cv::Mat mask = cv::Mat::zeros(reference.image().size(), CV_8UC1);
    for (const auto& [a, b] : segments) {
      cv::line(mask, reference.ToCanvas(a), reference.ToCanvas(b), cv::Scalar(255), 1, cv::LINE_8,
               4);
    }
    cv::Mat tinted;
    cv::addWeighted(reference.image(), 0.5,
                    cv::Mat(reference.image().size(), reference.image().type(), colour), 0.5, 0,
                    tinted);
    tinted.copyTo(reference.image(), mask);
    EXPECT_EQ(cv::norm(canvas.image(), reference.image(), cv::NORM_INF), 0) << "scale " << scale;
    EXPECT_GT(cv::countNonZero(mask), 100);
  }
}

TEST(Canvas, DefaultScaleKeepsThePictureNearTheMapsOwnSize) {
  EXPECT_EQ(DefaultScale(120, 100), 8);    // small maps are enlarged, at most 8 x
  EXPECT_EQ(DefaultScale(500, 500), 2);    // 1000 px
  EXPECT_EQ(DefaultScale(645, 573), 1);    // lab_a: its own size
  EXPECT_EQ(DefaultScale(1290, 1146), 1);  // never below 1
  EXPECT_EQ(DefaultScale(0, 0), 8);
}

TEST(Canvas, KeepsTheMapAsGreysUntilSomethingIsDrawn) {
  const std::string cells = {proto::CELL_FREE, proto::CELL_OCCUPIED, proto::CELL_UNKNOWN,
                             proto::CELL_FREE};
  Canvas canvas(cells, 2, 2, 2);
  const cv::Mat grey = canvas.UntouchedGrey().clone();
  ASSERT_EQ(grey.type(), CV_8UC1);
  ASSERT_EQ(grey.size(), cv::Size(4, 4));
  EXPECT_EQ(grey.at<uchar>(0, 0), 255);
  EXPECT_EQ(grey.at<uchar>(0, 2), 40);
  EXPECT_EQ(grey.at<uchar>(3, 1), 200);
  canvas.Line(At(0, 0), At(1, 1), cv::Scalar(0, 0, 255), 1);
  EXPECT_TRUE(canvas.UntouchedGrey().empty());  // drawn on: the BGR picture is the picture
  cv::Mat bgr;
  cv::cvtColor(grey, bgr, cv::COLOR_GRAY2BGR);
  EXPECT_EQ(canvas.image().at<cv::Vec3b>(3, 3), bgr.at<cv::Vec3b>(3, 3));
  EXPECT_EQ(canvas.image().at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 255));
}

}  // namespace
}  // namespace areagraph
