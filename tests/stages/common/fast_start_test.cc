// The pipeline's executables start without the shared libraries that
// cmake/FastStart.cmake links statically, and as position-dependent
// executables (docs/performance.md, issue 14, ninth pass).
#include <elf.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace areagraph::testing {
namespace {

constexpr const char* kFastStartTools[] = {
    "ag-import", "ag-clean",    "ag-voronoi", "ag-prune",       "ag-cut",        "ag-merge",
    "ag-match",  "ag-pipeline", "ag-run",     "ag-render",      "ag-inspect",    "ag-store",
    "ag-export", "ag-live",     "ag-listen",  "ag-bench-stage", "ag-bench-floor"};

std::string Ldd(const std::string& path) {
  FILE* pipe = popen(("ldd " + path).c_str(), "r");
  if (pipe == nullptr) return "";
  std::string libraries;
  char buffer[4096];
  for (size_t n; (n = fread(buffer, 1, sizeof(buffer), pipe)) > 0;) libraries.append(buffer, n);
  pclose(pipe);
  return libraries;
}

// The ELF file type: ET_EXEC for a position-dependent executable, ET_DYN
// for a position-independent one (or a shared library).
int ElfType(const std::string& path) {
  Elf64_Ehdr header{};
  std::ifstream(path, std::ios::binary).read(reinterpret_cast<char*>(&header), sizeof(header));
  return header.e_type;
}

TEST(FastStart, PipelineExecutablesLoadNoneOfTheStaticallyLinkedLibraries) {
#if !AG_FAST_START
  GTEST_SKIP() << "built with -DAG_FAST_START=OFF";
#endif
  for (const char* tool : kFastStartTools) {
    const std::string path = std::string(AG_BIN_DIR) + "/" + tool;
    const std::string libraries = Ldd(path);
    ASSERT_NE(libraries.find("libc.so"), std::string::npos) << "ldd " << path << ":\n" << libraries;
    for (const char* shared : {"libopencv_", "libprotobuf", "libsqlite3", "libcrypto", "libzstd",
                               "libpng", "libz.so", "libGLX", "libX11"}) {
      EXPECT_EQ(libraries.find(shared), std::string::npos) << tool << " loads " << shared;
    }
    EXPECT_EQ(ElfType(path), ET_EXEC) << tool << " is position-independent";
  }
}

TEST(FastStart, TestsAndTheCodecsModuleKeepTheSharedLibraries) {
  // The other side of the rule: what links libopencv_imgcodecs.so keeps the
  // shared OpenCV core it needs (one copy of OpenCV per module).
  const std::string module = Ldd(std::string(AG_BIN_DIR) + "/libag_image_codecs.so");
  EXPECT_NE(module.find("libopencv_core"), std::string::npos) << module;
  EXPECT_NE(module.find("libopencv_imgcodecs"), std::string::npos) << module;
  EXPECT_EQ(ElfType(std::string(AG_BIN_DIR) + "/ag-eval"), ET_DYN);
}

}  // namespace
}  // namespace areagraph::testing
