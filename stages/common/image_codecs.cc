#include "stages/common/image_codecs.h"

#include <dlfcn.h>
#include <unistd.h>

#include <climits>

#include "common/error.h"
#include "common/static_program.h"

namespace areagraph {
namespace {

constexpr const char* kModuleFile = "libag_image_codecs.so";

// The module's functions (image_codecs_module.cc).
struct Codecs {
  void (*decode)(const std::string& bytes, int flags, cv::Mat* image);
  bool (*have_reader)(const std::string& path);
  bool (*encode)(const std::string& extension, const cv::Mat& image, std::vector<uchar>* bytes,
                 const std::vector<int>& params);
};

// The folder of the running executable, with a trailing '/', or "".
std::string ExecutableFolder() {
  char path[PATH_MAX];
  const ssize_t length = readlink("/proc/self/exe", path, sizeof(path) - 1);
  if (length <= 0) return "";
  const std::string exe(path, static_cast<size_t>(length));
  return exe.substr(0, exe.rfind('/') + 1);
}

template <typename Function>
void Find(void* module, const char* name, Function* function) {
  *function = reinterpret_cast<Function>(dlsym(module, name));
  if (*function == nullptr) {
    throw Error(std::string("the image codecs module has no ") + name + "; rebuild areagraph");
  }
}

// Loads the module beside the executable, else wherever the dynamic loader
// finds it (LD_LIBRARY_PATH); once per process.
const Codecs& LoadedCodecs() {
  static const Codecs codecs = [] {
    if (LinkedStatically()) {
      throw Error("cannot load OpenCV's image codecs into a statically linked program");
    }
    void* module = dlopen((ExecutableFolder() + kModuleFile).c_str(), RTLD_NOW | RTLD_LOCAL);
    if (module == nullptr) module = dlopen(kModuleFile, RTLD_NOW | RTLD_LOCAL);
    if (module == nullptr) {
      throw Error(std::string("cannot load OpenCV's image codecs: ") + dlerror());
    }
    Codecs found{};
    Find(module, "ag_image_codecs_decode", &found.decode);
    Find(module, "ag_image_codecs_have_reader", &found.have_reader);
    Find(module, "ag_image_codecs_encode", &found.encode);
    return found;
  }();
  return codecs;
}

}  // namespace

cv::Mat DecodeImage(const std::string& bytes, int flags) {
  cv::Mat image;
  LoadedCodecs().decode(bytes, flags, &image);
  return image;
}

bool HaveImageReader(const std::string& path) { return LoadedCodecs().have_reader(path); }

bool EncodeImage(const std::string& extension, const cv::Mat& image, std::vector<uchar>* bytes,
                 const std::vector<int>& params) {
  return LoadedCodecs().encode(extension, image, bytes, params);
}

}  // namespace areagraph
