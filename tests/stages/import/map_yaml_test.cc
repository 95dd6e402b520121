// map_server YAML: parsing, defaults, and the trinary/scale/raw rules.
#include "stages/import/map_yaml.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "common/error.h"
#include "stages/import/grid_map_decoder.h"
#include "stages/import/import_stage.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::TempDir;
using testing::WriteFile;

constexpr proto::CellState F = proto::CELL_FREE;
constexpr proto::CellState O = proto::CELL_OCCUPIED;
constexpr proto::CellState U = proto::CELL_UNKNOWN;

// One row of greys that straddle map_server's default thresholds:
// p = (255 - v) / 255 > 0.65 is occupied (v <= 89), p < 0.196 free (v >= 206).
void WriteRow(const std::string& path) {
  const uint8_t greys[] = {0, 89, 90, 205, 206, 255};
  cv::Mat image(1, 6, CV_8UC1);
  for (int col = 0; col < 6; ++col) image.at<uint8_t>(0, col) = greys[col];
  ASSERT_TRUE(cv::imwrite(path, image));
}

proto::GridMap ImportWithYaml(const TempDir& dir, const std::string& yaml, const std::string& arg) {
  WriteRow(dir.File("row.png"));
  WriteFile(dir.File("row.yaml"), yaml);
  return ImportGridMap(ReadImportSource(dir.File(arg)), proto::ImportOptions());
}

TEST(MapYamlTest, DefaultsFollowMapServer) {
  const MapYaml yaml = ParseMapYaml("image: a.png\nresolution: 0.1\n", "/maps/a.yaml", true);
  EXPECT_EQ(yaml.image_path, "/maps/a.png");
  EXPECT_DOUBLE_EQ(yaml.resolution_m, 0.1);
  EXPECT_DOUBLE_EQ(yaml.origin_x_m, 0);
  EXPECT_FALSE(yaml.negate);
  EXPECT_DOUBLE_EQ(yaml.occupied_thresh, 0.65);
  EXPECT_DOUBLE_EQ(yaml.free_thresh, 0.196);
  EXPECT_EQ(yaml.mode, MapYaml::Mode::kTrinary);
}

TEST(MapYamlTest, ImageIsRelativeToTheYamlUnlessAbsolute) {
  EXPECT_EQ(ParseMapYaml("image: ../img/a.pgm\nresolution: 1\n", "maps/x/a.yaml", true).image_path,
            "maps/img/a.pgm");
  EXPECT_EQ(ParseMapYaml("image: /abs/a.pgm\nresolution: 1\n", "maps/a.yaml", true).image_path,
            "/abs/a.pgm");
}

TEST(MapYamlTest, TrinaryThresholds) {
  TempDir dir;
  const proto::GridMap grid = ImportWithYaml(dir, "image: row.png\nresolution: 0.05\n", "row.png");
  EXPECT_EQ(grid.cells(), std::string({O, O, U, U, F, F}));
}

TEST(MapYamlTest, NegateInvertsGreys) {
  TempDir dir;
  const proto::GridMap grid =
      ImportWithYaml(dir, "image: row.png\nresolution: 0.05\nnegate: 1\n", "row.png");
  // Negated, p = v / 255: 0 is free, 89 and 90 (0.35) unknown, 205 and up
  // (0.80) occupied.
  EXPECT_EQ(grid.cells(), std::string({F, U, U, O, O, O}));
}

TEST(MapYamlTest, OriginAndResolutionFillTheFrame) {
  TempDir dir;
  const proto::GridMap grid = ImportWithYaml(
      dir, "image: row.png\nresolution: 0.025\norigin: [-12.5, 3.25, 0.5]\n", "row.yaml");
  EXPECT_DOUBLE_EQ(grid.frame().resolution_m(), 0.025);
  EXPECT_DOUBLE_EQ(grid.frame().origin_x_m(), -12.5);
  EXPECT_DOUBLE_EQ(grid.frame().origin_y_m(), 3.25);
  EXPECT_DOUBLE_EQ(grid.frame().origin_yaw_rad(), 0.5);
  EXPECT_EQ(grid.frame().width_px(), 6);
  EXPECT_EQ(grid.frame().height_px(), 1);
}

TEST(MapYamlTest, OwnThresholds) {
  TempDir dir;
  const proto::GridMap grid = ImportWithYaml(
      dir, "image: row.png\nresolution: 0.05\noccupied_thresh: 0.9\nfree_thresh: 0.5\n", "row.png");
  // p: 1.0, 0.65, 0.647, 0.196, 0.192, 0
  EXPECT_EQ(grid.cells(), std::string({O, U, U, F, F, F}));
}

TEST(MapYamlTest, RawModeReadsOccupancyPercent) {
  GreyToCell rule = MapServerRule(ParseMapYaml("resolution: 1\nmode: raw\n", "r.yaml", false));
  EXPECT_EQ(rule[0], F);
  EXPECT_EQ(rule[19], F);  // 0.19 < 0.196
  EXPECT_EQ(rule[20], U);  // 0.20
  EXPECT_EQ(rule[65], U);  // 0.65 is not above 0.65
  EXPECT_EQ(rule[66], O);
  EXPECT_EQ(rule[100], O);
  EXPECT_EQ(rule[101], U);  // above 100: no occupancy value
  EXPECT_EQ(rule[255], U);
}

TEST(MapYamlTest, ScaleModeClassifiesLikeTrinary) {
  EXPECT_EQ(MapServerRule(ParseMapYaml("resolution: 1\nmode: scale\n", "s.yaml", false)),
            MapServerRule(ParseMapYaml("resolution: 1\n", "t.yaml", false)));
}

TEST(MapYamlTest, NegateAcceptsBooleans) {
  EXPECT_TRUE(ParseMapYaml("resolution: 1\nnegate: true\n", "n.yaml", false).negate);
  EXPECT_FALSE(ParseMapYaml("resolution: 1\nnegate: 0\n", "n.yaml", false).negate);
}

TEST(MapYamlTest, BadValuesNameKeyAndFile) {
  const std::pair<std::string, std::string> cases[] = {
      {"image: a.png\n", "lacks 'resolution'"},
      {"resolution: 1\n", "lacks 'image'"},
      {"image: a.png\nresolution: -0.05\n", "'resolution' must be a resolution in [0.0001, 1000]"},
      {"image: a.png\nresolution: .nan\n", "'resolution' must be finite"},
      {"image: a.png\nresolution: .inf\n", "'resolution' must be finite"},
      {"image: a.png\nresolution: 1001\n", "'resolution' must be a resolution in [0.0001, 1000]"},
      {"image: a.png\nresolution: fast\n", "'resolution' must be a number"},
      {"image: a.png\nresolution: 1\norigin: [1]\n", "'origin' must be [x, y, yaw]"},
      {"image: a.png\nresolution: 1\norigin: [1, 2]\n", "'origin' must be [x, y, yaw] (three"},
      {"image: a.png\nresolution: 1\norigin: [1, 2, 0, 4]\n", "'origin' must be [x, y, yaw]"},
      {"image: a.png\nresolution: 1\norigin: [1.7e308, 0, 0]\n",
       "'origin': origin x and y must be finite metres within +-1e+08, got 1.7e+308, 0"},
      {"image: a.png\nresolution: 1\norigin: [0, -1e9, 0]\n", "within +-1e+08"},
      {"image: a.png\nresolution: 1\norigin: [.nan, 0, 0]\n", "'origin x' must be finite"},
      {"image: a.png\nresolution: 1\norigin: [0, .inf, 0]\n", "'origin y' must be finite"},
      {"image: a.png\nresolution: 1\norigin: [0, 0, 1e300]\n",
       "origin yaw must be finite radians within +-2 pi"},
      {"image: a.png\nresolution: 1e-300\n", "must be a resolution in [0.0001, 1000]"},
      {"image: a.png\nresolution: 0.05\nresolution: 0.1\n", "'resolution' is given twice"},
      {"image: a.png\nimage: b.png\nresolution: 0.05\n", "'image' is given twice"},
      {"image: a.png\nresolution: 1\norigin: [0, 0, 0]\norigin: [5, 5, 0]\n",
       "'origin' is given twice"},
      {"image: a.png\nresolution: 1\norigin: [1, x, 0]\n", "'origin y' must be a number"},
      {"image: a.png\nresolution: 1\nnegate: 2\n", "'negate' must be 0 or 1"},
      {"image: a.png\nresolution: 1\nfree_thresh: 1.5\n", "'free_thresh' must lie in [0, 1]"},
      {"image: a.png\nresolution: 1\nfree_thresh: 0.7\n", "must not exceed 'occupied_thresh'"},
      {"image: a.png\nresolution: 1\nmode: fancy\n", "'mode' must be trinary, scale or raw"},
      {"image: a.png\nresolution: [1\n", "is malformed"},
      {"just text\n", "expected keys such as 'image' and 'resolution'"},
      {"", "expected keys such as 'image' and 'resolution'"},
  };
  for (const auto& [yaml, message] : cases) {
    try {
      ParseMapYaml(yaml, "m.yaml", true);
      ADD_FAILURE() << "accepted: " << yaml;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("'m.yaml'"), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    }
  }
}

TEST(MapYamlTest, YamlBesideTheImageIsFoundAndDigested) {
  TempDir dir;
  WriteRow(dir.File("row.png"));
  const ImportSource without = ReadImportSource(dir.File("row.png"));
  EXPECT_FALSE(without.yaml);
  WriteFile(dir.File("row.yaml"), "image: row.png\nresolution: 0.5\n");
  const ImportSource with = ReadImportSource(dir.File("row.png"));
  ASSERT_TRUE(with.yaml);
  EXPECT_EQ(*with.yaml_path, dir.File("row.yaml"));
  EXPECT_NE(with.Digest(), without.Digest());
  EXPECT_EQ(ImportGridMap(with, proto::ImportOptions()).frame().resolution_m(), 0.5);
}

TEST(ClassifyCellsTest, EveryPixelByItsGreyRowByRow) {
  // A view into a wider image: rows are not contiguous.
  cv::Mat wide(37, 53, CV_8UC1);
  cv::randu(wide, 0, 256);
  const cv::Mat grey = wide(cv::Rect(3, 2, 41, 33));
  MapYaml raw;
  raw.mode = MapYaml::Mode::kRaw;
  raw.negate = true;
  // Rules of a few steps (sixteen pixels at a time) and of many (the table).
  GreyToCell four_steps = GreyThresholdRule(proto::ImportOptions()), any;
  for (int g = 0; g < 256; ++g) {
    four_steps[g] = g < 3 ? O : g < 100 ? U : g < 101 ? F : g < 255 ? O : U;
    any[g] = proto::CellState(std::rand() % 3);
  }
  for (const GreyToCell& rule : {GreyThresholdRule(proto::ImportOptions()),
                                 MapServerRule(MapYaml()), MapServerRule(raw), four_steps, any}) {
    const std::string cells = ClassifyCells(grey, rule);
    ASSERT_EQ(cells.size(), size_t(grey.rows) * grey.cols);
    for (int row = 0; row < grey.rows; ++row) {
      for (int col = 0; col < grey.cols; ++col) {
        ASSERT_EQ(cells[size_t(row) * grey.cols + col], char(rule[grey.at<uint8_t>(row, col)]))
            << row << ", " << col;
      }
    }
  }
}

}  // namespace
}  // namespace areagraph
