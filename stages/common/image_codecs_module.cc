// The module libag_image_codecs.so: OpenCV's codecs behind unmangled names,
// for image_codecs.cc to find with dlsym. C++ types cross the boundary: the
// module and its loader come from one build.
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

extern "C" {

// cv::imdecode into *image.
void ag_image_codecs_decode(const std::string& bytes, int flags, cv::Mat* image) {
  const std::vector<uchar> buffer(bytes.begin(), bytes.end());
  *image = cv::imdecode(buffer, flags);
}

// cv::haveImageReader.
bool ag_image_codecs_have_reader(const std::string& path) { return cv::haveImageReader(path); }

// cv::imencode.
bool ag_image_codecs_encode(const std::string& extension, const cv::Mat& image,
                            std::vector<uchar>* bytes, const std::vector<int>& params) {
  return cv::imencode(extension, image, *bytes, params);
}
}
