#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace areagraph::testing {

// PNG colour types that cv::imwrite cannot produce, written by hand (zlib
// for the pixel data) so that the decoder can be tested on them.

// An 8-bit palette image: `indices` row-major into `palette` (RGB triples);
// `alpha` (optional, one per palette entry) becomes a tRNS chunk.
std::string PalettePng(int width, int height, const std::vector<uint8_t>& indices,
                       const std::vector<uint8_t>& palette_rgb,
                       const std::vector<uint8_t>& alpha = {});

// A grey+alpha image; `samples` holds (grey, alpha) pairs row-major, each
// sample 8 or 16 bits as `bit_depth` says.
std::string GreyAlphaPng(int width, int height, const std::vector<uint16_t>& samples,
                         int bit_depth);

// Just a signature, an IHDR claiming `width` x `height` (8-bit grey), a tiny
// IDAT and IEND: what a decompression bomb or a 0-width image looks like
// from the outside.
std::string HeaderOnlyPng(uint32_t width, uint32_t height);

}  // namespace areagraph::testing
