#include "stages/geometry/near_free_mask.h"

#include "proto/artifacts.pb.h"

namespace areagraph {

std::vector<uint8_t> NearFreeMask(const std::string& cells, int width, int height) {
  const size_t count = size_t(width) * size_t(height);
  const uint8_t* state = reinterpret_cast<const uint8_t*>(cells.data());
  // Pass 1: a free cell within one column, in the same row. The row's free
  // flags sit in a buffer with a zero on either side, so the loop has no
  // branches and vectorises.
  std::vector<uint8_t> in_row(count);
  std::vector<uint8_t> padded(size_t(width) + 2, 0);
  for (int row = 0; row < height; ++row) {
    const uint8_t* in = state + size_t(row) * width;
    for (int col = 0; col < width; ++col) padded[col + 1] = in[col] == proto::CELL_FREE;
    uint8_t* out = in_row.data() + size_t(row) * width;
    const uint8_t* flags = padded.data();
    for (int col = 0; col < width; ++col) out[col] = flags[col] | flags[col + 1] | flags[col + 2];
  }
  // Pass 2: ... and within one row.
  std::vector<uint8_t> mask(count);
  for (int row = 0; row < height; ++row) {
    const uint8_t* here = in_row.data() + size_t(row) * width;
    const uint8_t* above = row > 0 ? here - width : here;
    const uint8_t* below = row + 1 < height ? here + width : here;
    uint8_t* out = mask.data() + size_t(row) * width;
    for (int col = 0; col < width; ++col) out[col] = above[col] | here[col] | below[col];
  }
  return mask;
}

}  // namespace areagraph
