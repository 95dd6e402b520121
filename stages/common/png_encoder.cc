#include "stages/common/png_encoder.h"

#include <png.h>

#include <csetjmp>
#include <vector>

namespace areagraph {
namespace {

// Appends libpng's output to the string.
void AppendBytes(png_structp png, png_bytep data, png_size_t count) {
  static_cast<std::string*>(png_get_io_ptr(png))
      ->append(reinterpret_cast<const char*>(data), count);
}

void NoFlush(png_structp) {}

// Errors (out of memory, mostly) end the encoding at Encode's setjmp.
[[noreturn]] void LongjmpOnError(png_structp png, png_const_charp) { png_longjmp(png, 1); }
void IgnoreWarning(png_structp, png_const_charp) {}

// libpng's write structures, freed on every path.
struct WriteStructs {
  png_structp png = nullptr;
  png_infop info = nullptr;
  ~WriteStructs() { png_destroy_write_struct(&png, info != nullptr ? &info : nullptr); }
};

// The encoding proper; libpng reports errors by longjmp to here, so nothing
// with a destructor lives in this frame (the caller owns `rows` and `png_out`).
bool Encode(WriteStructs& structs, const cv::Mat& image, int compression, int filters,
            std::vector<png_bytep>* rows, std::string* png_out) {
  png_structp png = structs.png;
  png_infop info = structs.info;
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_write_fn(png, png_out, AppendBytes, NoFlush);
  const int channels = image.channels();
  const int colour_type = channels == 1   ? PNG_COLOR_TYPE_GRAY
                          : channels == 3 ? PNG_COLOR_TYPE_RGB
                                          : PNG_COLOR_TYPE_RGB_ALPHA;
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.cols),
               static_cast<png_uint_32>(image.rows), 8, colour_type, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, compression);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, filters);
  png_write_info(png, info);
  if (channels > 1) png_set_bgr(png);
  rows->resize(image.rows);
  for (int y = 0; y < image.rows; ++y) (*rows)[y] = const_cast<png_bytep>(image.ptr<uchar>(y));
  png_write_image(png, rows->data());
  png_write_end(png, nullptr);
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
  WriteStructs structs;
  structs.png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, LongjmpOnError, IgnoreWarning);
  if (structs.png == nullptr) return false;
  structs.info = png_create_info_struct(structs.png);
  if (structs.info == nullptr) return false;
  std::vector<png_bytep> rows;  // outside Encode's setjmp frame
  if (!Encode(structs, image, compression, filters, &rows, png)) {
    png->clear();
    return false;
  }
  return true;
}

}  // namespace areagraph
