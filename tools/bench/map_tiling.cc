#include "tools/bench/map_tiling.h"

#include <algorithm>

namespace areagraph {
namespace {

constexpr unsigned char kFree = 255;
constexpr unsigned char kWall = 0;
constexpr int kFreeMinGrey = 250;  // ag-import's default for maps without a YAML
constexpr int kHalfWidth = 10;     // corridor of 2 * 10 + 1 px, about 1 m at 0.05 m/px

bool IsFree(unsigned char grey) { return grey >= kFreeMinGrey; }

// The row (of `map`, or of its transpose) whose longest run of free cells is
// longest, kept kHalfWidth + 1 px away from the border so the corridor and
// its walls fit.
int LongestFreeRunRow(const cv::Mat& map) {
  int best_row = -1, best_run = 0;
  for (int y = kHalfWidth + 1; y < map.rows - kHalfWidth - 1; ++y) {
    const unsigned char* row = map.ptr<unsigned char>(y);
    int run = 0;
    for (int x = 0; x < map.cols; ++x) {
      run = IsFree(row[x]) ? run + 1 : 0;
      if (run > best_run) best_run = run, best_row = y;
    }
  }
  return best_row;
}

// Joins copies along rows (the caller transposes for columns): the corridor
// leaves each copy at its last free cell in row `y` and enters the next copy
// at its first one.
void JoinAlongRows(const cv::Mat& map, int tiles, int y, cv::Mat& tiled) {
  const unsigned char* row = map.ptr<unsigned char>(y);
  int first = -1, last = -1;
  for (int x = 0; x < map.cols; ++x) {
    if (!IsFree(row[x])) continue;
    if (first < 0) first = x;
    last = x;
  }
  if (first < 0) return;
  for (int ty = 0; ty < tiles; ++ty) {
    const int cy = ty * map.rows + y;
    for (int tx = 0; tx + 1 < tiles; ++tx) {
      const int from = tx * map.cols + last, to = (tx + 1) * map.cols + first;
      for (int x = from; x <= to; ++x) {
        for (int dy = -kHalfWidth; dy <= kHalfWidth; ++dy)
          tiled.at<unsigned char>(cy + dy, x) = kFree;
        for (int dy : {-kHalfWidth - 1, kHalfWidth + 1}) {
          unsigned char& cell = tiled.at<unsigned char>(cy + dy, x);
          if (!IsFree(cell)) cell = kWall;
        }
      }
    }
  }
}

}  // namespace

cv::Mat TileMap(const cv::Mat& map, int tiles) {
  cv::Mat tiled;
  cv::repeat(map, tiles, tiles, tiled);
  if (tiles < 2) return tiled;
  const int row = LongestFreeRunRow(map);
  if (row >= 0) JoinAlongRows(map, tiles, row, tiled);
  const cv::Mat map_t = map.t();
  cv::Mat tiled_t = tiled.t();
  const int column = LongestFreeRunRow(map_t);
  if (column >= 0) JoinAlongRows(map_t, tiles, column, tiled_t);
  return tiled_t.t();
}

}  // namespace areagraph
