#include "stages/geometry/enclosed_pockets.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "stages/geometry/region_boxes.h"

namespace areagraph {

void FillEnclosedPockets(double max_pocket_px, cv::Mat* obstacle) {
  const int width = obstacle->cols, height = obstacle->rows;
  // The free pieces over the rows' runs: no label raster, and a pocket's
  // cells are filled run by run.
  std::vector<PieceRun> runs;
  std::vector<int> piece_of_run;
  const int count = RunPieces(*obstacle == 0, &runs, &piece_of_run);
  // Each piece's box, [x0, x1) x [y0, y1).
  struct Box {
    int x0, y0, x1, y1;
  };
  std::vector<Box> box(count, Box{width, height, 0, 0});
  for (size_t i = 0; i < runs.size(); ++i) {
    Box& b = box[piece_of_run[i]];
    b.x0 = std::min(b.x0, runs[i].begin), b.x1 = std::max(b.x1, runs[i].end);
    b.y0 = std::min(b.y0, runs[i].row), b.y1 = std::max(b.y1, runs[i].row + 1);
  }
  std::vector<uint8_t> fill(count, 0);
  for (int k = 0; k < count; ++k) {
    const Box& b = box[k];
    const bool border = b.x0 == 0 || b.y0 == 0 || b.x1 == width || b.y1 == height;
    fill[k] = !border && std::max(b.x1 - b.x0, b.y1 - b.y0) <= max_pocket_px;
  }
  for (size_t i = 0; i < runs.size(); ++i) {
    if (!fill[piece_of_run[i]]) continue;
    uint8_t* row = obstacle->ptr<uint8_t>(runs[i].row);
    std::fill(row + runs[i].begin, row + runs[i].end, 255);
  }
}

}  // namespace areagraph
