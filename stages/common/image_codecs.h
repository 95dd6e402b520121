#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace areagraph {

// OpenCV's image codecs (libopencv_imgcodecs), loaded on first use from the
// module libag_image_codecs.so beside the executable: linked directly, they
// pull some 120 shared libraries (GDAL, poppler, HDF5, ...) into every start
// of ag-import, ag-run and ag-render, about 0.1 s and 40 MB each, although a
// map is decoded in a few milliseconds. Each function behaves as the
// cv:: function it names (and throws cv::Exception as that does); loading
// the module throws areagraph::Error naming it.

// cv::imdecode.
cv::Mat DecodeImage(const std::string& bytes, int flags);
// cv::haveImageReader.
bool HaveImageReader(const std::string& path);
// cv::imencode: false when the image cannot be encoded as `extension`.
bool EncodeImage(const std::string& extension, const cv::Mat& image, std::vector<uchar>* bytes,
                 const std::vector<int>& params = {});

}  // namespace areagraph
