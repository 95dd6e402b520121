#include "stages/common/png_encoder.h"

#include <png.h>
#include <zlib.h>

#include <csetjmp>
#include <optional>
#include <vector>

#include "stages/common/png_palette.h"
#include "stages/common/png_write_structs.h"

namespace areagraph {
namespace {

// Declares the picture's palette (as RGB) and its bits per index; libpng
// packs the one-byte indices into them.
void SetPalette(png_structp png, png_infop info, const cv::Mat& image,
                const std::vector<cv::Vec3b>& colours) {
  std::vector<png_color> entries;
  for (const cv::Vec3b& bgr : colours) entries.push_back({bgr[2], bgr[1], bgr[0]});
  const int depth = PaletteBitDepth(colours.size());
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.cols),
               static_cast<png_uint_32>(image.rows), depth, PNG_COLOR_TYPE_PALETTE,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_PLTE(png, info, entries.data(), static_cast<int>(entries.size()));
}

// The encoding proper; libpng reports errors by longjmp to here, so nothing
// with a destructor lives in this frame (the caller owns `rows`, `palette`
// and `png_out`). A picture with a palette is written as its indices.
bool Encode(PngWriteStructs& structs, const cv::Mat& image, int compression, int filters,
            const std::optional<PalettePicture>& palette, std::vector<png_bytep>* rows,
            std::string* png_out) {
  png_structp png = structs.png;
  png_infop info = structs.info;
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_write_fn(png, png_out, PngAppendBytes, PngNoFlush);
  const int channels = image.channels();
  const int colour_type = channels == 1   ? PNG_COLOR_TYPE_GRAY
                          : channels == 3 ? PNG_COLOR_TYPE_RGB
                                          : PNG_COLOR_TYPE_RGB_ALPHA;
  if (palette) {
    SetPalette(png, info, image, palette->colours);
  } else {
    png_set_IHDR(png, info, static_cast<png_uint_32>(image.cols),
                 static_cast<png_uint_32>(image.rows), 8, colour_type, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  }
  png_set_compression_level(png, compression);
  // A palette picture (a map, flat drawings) is runs of one index, and zeros
  // where a row repeats the one above ("up" filter): zlib's run-only search
  // (Z_RLE) finds those with fewer instructions than its default, as for
  // ag-render's import picture (tools/render/map_png.cc).
  if (palette) png_set_compression_strategy(png, Z_RLE);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, filters);
  png_write_info(png, info);
  if (palette) {
    if (PaletteBitDepth(palette->colours.size()) < 8) png_set_packing(png);
  } else if (channels > 1) {
    png_set_bgr(png);
  }
  const cv::Mat& samples = palette ? palette->indices : image;
  rows->resize(image.rows);
  for (int y = 0; y < image.rows; ++y) {
    (*rows)[y] = const_cast<png_bytep>(samples.ptr<uchar>(y));
  }
  png_write_image(png, rows->data());
  png_write_end(png, nullptr);
  return true;
}

}  // namespace

namespace {

// EncodePngWithLibpng's body: `image` with its palette form, if it has one.
bool EncodeWithPalette(const cv::Mat& image, const std::optional<PalettePicture>& palette,
                       int compression, int filters, std::string* png) {
  PngWriteStructs structs;
  structs.png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, PngLongjmpOnError, PngIgnoreWarning);
  if (structs.png == nullptr) return false;
  structs.info = png_create_info_struct(structs.png);
  if (structs.info == nullptr) return false;
  std::vector<png_bytep> rows;
  if (!Encode(structs, image, compression, filters, palette, &rows, png)) {
    png->clear();
    return false;
  }
  return true;
}

}  // namespace

bool EncodePngWithLibpng(const cv::Mat& image, int compression, int filters, std::string* png) {
  png->clear();
  const int channels = image.channels();
  if (image.depth() != CV_8U || (channels != 1 && channels != 3 && channels != 4) ||
      image.empty()) {
    return false;
  }
  // Outside Encode's setjmp frame: a BGR picture of few colours (maps, flat
  // drawings) as palette indices, a third of the bytes or less to filter and
  // deflate, and a smaller file.
  const std::optional<PalettePicture> palette =
      channels == 3 ? ToPalette(image) : std::optional<PalettePicture>();
  return EncodeWithPalette(image, palette, compression, filters, png);
}

bool EncodeGreyAsColourPng(const cv::Mat& grey, int compression, int filters, std::string* png) {
  png->clear();
  if (grey.type() != CV_8UC1 || grey.empty()) return false;
  return EncodeWithPalette(grey, GreyToPalette(grey), compression, filters, png);
}

}  // namespace areagraph
