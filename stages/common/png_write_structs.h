#pragma once

// libpng's write plumbing shared by the stages' PNG encoder and ag-render's
// map pictures: output appended to a string, errors ending at the caller's
// setjmp, and the write structures freed on every path.
#include <png.h>

#include <string>

namespace areagraph {

// Appends libpng's output to the std::string given as the io pointer.
inline void PngAppendBytes(png_structp png, png_bytep data, png_size_t count) {
  static_cast<std::string*>(png_get_io_ptr(png))
      ->append(reinterpret_cast<const char*>(data), count);
}

inline void PngNoFlush(png_structp) {}

// Errors (out of memory, mostly) end the encoding at the caller's setjmp.
[[noreturn]] inline void PngLongjmpOnError(png_structp png, png_const_charp) {
  png_longjmp(png, 1);
}
inline void PngIgnoreWarning(png_structp, png_const_charp) {}

// libpng's write structures, freed on every path.
struct PngWriteStructs {
  png_structp png = nullptr;
  png_infop info = nullptr;
  ~PngWriteStructs() { png_destroy_write_struct(&png, info != nullptr ? &info : nullptr); }
};

}  // namespace areagraph
