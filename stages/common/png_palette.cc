#include "stages/common/png_palette.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <opencv2/core.hpp>

namespace areagraph {
namespace {

// Colours seen so far: open addressing over 24-bit keys, with room to spare
// for 256 colours so that probes stay short.
class ColourIndex {
 public:
  ColourIndex() { keys_.fill(kEmpty); }

  // The colour's index, added when new; -1 when a 257th colour comes.
  int Find(uint32_t key, PalettePicture& out) {
    uint32_t slot = (key * 2654435761u) >> (32 - kBits);
    while (keys_[slot] != kEmpty) {
      if (keys_[slot] == key) return values_[slot];
      slot = (slot + 1) & (kSlots - 1);
    }
    if (out.colours.size() == 256) return -1;
    keys_[slot] = key;
    values_[slot] = static_cast<uint8_t>(out.colours.size());
    out.colours.emplace_back(key & 0xff, (key >> 8) & 0xff, key >> 16);
    return values_[slot];
  }

 private:
  static constexpr int kBits = 10;
  static constexpr uint32_t kSlots = 1u << kBits, kEmpty = 0xffffffffu;
  std::array<uint32_t, kSlots> keys_;
  std::array<uint8_t, kSlots> values_;
};

}  // namespace

std::optional<PalettePicture> ToPalette(const cv::Mat& bgr) {
  if (bgr.type() != CV_8UC3 || bgr.empty()) return std::nullopt;
  PalettePicture out;
  out.indices.create(bgr.size(), CV_8UC1);
  ColourIndex index;
  uint32_t last_key = 0xffffffffu;
  uint8_t last_value = 0;
  const int width = bgr.cols;
  const size_t row_bytes = static_cast<size_t>(width) * 3;
  for (int y = 0; y < bgr.rows; ++y) {
    const uint8_t* pixel = bgr.ptr<uint8_t>(y);
    uint8_t* target = out.indices.ptr<uint8_t>(y);
    // A row like the one above (every row of an upscaled picture has a
    // twin) takes its indices whole.
    if (y > 0 && std::memcmp(pixel, bgr.ptr<uint8_t>(y - 1), row_bytes) == 0) {
      std::memcpy(target, out.indices.ptr<uint8_t>(y - 1), width);
      continue;
    }
    for (int x = 0; x < width; ++x, pixel += 3) {
      const uint32_t key = pixel[0] | (pixel[1] << 8) | (pixel[2] << 16);
      if (key != last_key) {  // runs of one colour skip the table
        const int value = index.Find(key, out);
        if (value < 0) return std::nullopt;
        last_key = key;
        last_value = static_cast<uint8_t>(value);
      }
      target[x] = last_value;
    }
  }
  return out;
}

PalettePicture GreyToPalette(const cv::Mat& grey) {
  CV_Assert(grey.type() == CV_8UC1);
  // Greys numbered in the order they first appear, as ToPalette numbers the
  // BGR colours (g, g, g) of the same picture; then one table pass, a plain
  // loop (cv::LUT would start TBB's worker threads for a big picture: 5 ms
  // of CPU, more than the pass).
  PalettePicture out;
  std::array<uint8_t, 256> index_of{};
  std::array<bool, 256> seen{};
  const int width = grey.cols;
  for (int y = 0; y < grey.rows && out.colours.size() < 256; ++y) {
    const uint8_t* pixel = grey.ptr<uint8_t>(y);
    // A row like the one above (every row of an upscaled picture has a
    // twin) has no grey of its own.
    if (y > 0 && std::memcmp(pixel, grey.ptr<uint8_t>(y - 1), width) == 0) continue;
    for (int x = 0; x < width; ++x) {
      const uint8_t value = pixel[x];
      if (seen[value]) continue;
      seen[value] = true;
      index_of[value] = static_cast<uint8_t>(out.colours.size());
      out.colours.emplace_back(value, value, value);
    }
  }
  out.indices.create(grey.size(), CV_8UC1);
  for (int y = 0; y < grey.rows; ++y) {
    const uint8_t* pixel = grey.ptr<uint8_t>(y);
    uint8_t* index = out.indices.ptr<uint8_t>(y);
    for (int x = 0; x < width; ++x) index[x] = index_of[pixel[x]];
  }
  return out;
}

int PaletteBitDepth(size_t colours) {
  return colours <= 2 ? 1 : colours <= 4 ? 2 : colours <= 16 ? 4 : 8;
}

}  // namespace areagraph
