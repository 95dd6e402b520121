#include "stages/import/png_grey_decoder.h"

#include <png.h>

#include <csetjmp>
#include <cstdint>
#include <cstring>
#include <vector>

namespace areagraph {
namespace {

bool IsLittleEndian() {
  const uint16_t one = 1;
  uint8_t first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

// Feeds libpng from the file's bytes.
struct ByteReader {
  const std::string* bytes;
  size_t offset = 0;
};

void ReadBytes(png_structp png, png_bytep out, png_size_t count) {
  auto* reader = static_cast<ByteReader*>(png_get_io_ptr(png));
  if (reader->bytes->size() - reader->offset < count) png_error(png, "truncated");
  std::memcpy(out, reader->bytes->data() + reader->offset, count);
  reader->offset += count;
}

// Warnings change nothing here; OpenCV's decoder prints them instead.
void IgnoreWarning(png_structp, png_const_charp) {}

// Errors return to Decode's setjmp without a word: the caller falls back to
// OpenCV, which reports them.
[[noreturn]] void SilentError(png_structp png, png_const_charp) { png_longjmp(png, 1); }

// libpng's read structures, freed on every path.
struct ReadStructs {
  png_structp png = nullptr;
  png_infop info = nullptr;
  ~ReadStructs() { png_destroy_read_struct(&png, info != nullptr ? &info : nullptr, nullptr); }
};

// The decode proper; libpng reports errors by longjmp to here, so nothing
// with a destructor lives in this frame (the caller owns `grey` and `rows`).
bool Decode(ReadStructs& structs, ByteReader& reader, cv::Mat* grey, std::vector<png_bytep>* rows) {
  png_structp png = structs.png;
  png_infop info = structs.info;
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_read_fn(png, &reader, ReadBytes);
  // zlib's Adler-32 of the image data goes unchecked (a tenth of the decode):
  // every chunk's CRC-32, still checked, covers the same compressed bytes.
  png_set_option(png, PNG_IGNORE_ADLER32, PNG_OPTION_ON);
  png_read_info(png, info);
  const int bit_depth = png_get_bit_depth(png, info);
  const int color_type = png_get_color_type(png, info);
  if (bit_depth > 16 || png_get_valid(png, info, PNG_INFO_eXIf)) return false;
  // 16-bit samples stay 16-bit (IMREAD_ANYDEPTH), in the host's byte order.
  if (bit_depth == 16 && IsLittleEndian()) png_set_swap(png);
  png_set_strip_alpha(png);
  if (color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if ((color_type & PNG_COLOR_MASK_COLOR) == 0 && bit_depth < 8) {
    png_set_expand_gray_1_2_4_to_8(png);
  }
  png_set_rgb_to_gray(png, 1, 0.299, 0.587);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  const png_uint_32 width = png_get_image_width(png, info);
  const png_uint_32 height = png_get_image_height(png, info);
  const int out_depth = png_get_bit_depth(png, info);
  if (png_get_channels(png, info) != 1 || out_depth != (bit_depth == 16 ? 16 : 8)) return false;
  grey->create(static_cast<int>(height), static_cast<int>(width),
               out_depth == 16 ? CV_16UC1 : CV_8UC1);
  rows->resize(height);
  for (png_uint_32 y = 0; y < height; ++y) (*rows)[y] = grey->ptr<uchar>(static_cast<int>(y));
  png_read_image(png, rows->data());
  png_read_end(png, nullptr);
  return true;
}

}  // namespace

bool DecodeCommonPngToGrey(const std::string& bytes, cv::Mat* grey) {
  grey->release();
  if (bytes.size() < 8 || png_sig_cmp(reinterpret_cast<png_const_bytep>(bytes.data()), 0, 8)) {
    return false;
  }
  ReadStructs structs;
  structs.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, SilentError, IgnoreWarning);
  if (structs.png == nullptr) return false;
  structs.info = png_create_info_struct(structs.png);
  if (structs.info == nullptr) return false;
  ByteReader reader{&bytes};
  std::vector<png_bytep> rows;  // outside Decode's setjmp frame
  if (!Decode(structs, reader, grey, &rows)) {
    grey->release();
    return false;
  }
  return true;
}

}  // namespace areagraph
