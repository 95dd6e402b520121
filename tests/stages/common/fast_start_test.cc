// The pipeline's executables start without the shared libraries that
// cmake/FastStart.cmake links statically or loads on first use, and as
// position-dependent executables (docs/performance.md, "Start-up").
#include <elf.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

constexpr const char* kFastStartTools[] = {
    "ag-import", "ag-clean",    "ag-voronoi",     "ag-prune",      "ag-cut",   "ag-merge",
    "ag-match",  "ag-pipeline", "ag-run",         "ag-inspect",    "ag-store", "ag-export",
    "ag-live",   "ag-listen",   "ag-bench-stage", "ag-bench-floor"};

// Linked with glibc too (ag_fully_static): no dynamic loader at all.
constexpr const char* kFullyStaticTools[] = {"ag-render"};

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

// Linked statically, or (x86-64: cmake/lazy_libraries.sh) loaded on first use.
constexpr const char* kNotLoadedAtStart[] = {
    "libopencv_", "libprotobuf", "libsqlite3", "libcrypto", "libzstd",
    "libpng",     "libz.so",     "libGLX",     "libX11",    "libyaml-cpp",
#if defined(__x86_64__)
    "libtbb",     "liblapack",   "libblas",    "liblcm",    "libglib",
#endif
};

TEST(FastStart, PipelineExecutablesLoadNoneOfTheStaticallyLinkedLibraries) {
#if !AG_FAST_START
  GTEST_SKIP() << "built with -DAG_FAST_START=OFF";
#endif
  for (const char* tool : kFastStartTools) {
    const std::string path = std::string(AG_BIN_DIR) + "/" + tool;
    const std::string libraries = Ldd(path);
    ASSERT_NE(libraries.find("libc.so"), std::string::npos) << "ldd " << path << ":\n" << libraries;
    for (const char* shared : kNotLoadedAtStart) {
      EXPECT_EQ(libraries.find(shared), std::string::npos) << tool << " loads " << shared;
    }
    EXPECT_EQ(ElfType(path), ET_EXEC) << tool << " is position-independent";
  }
}

// Whether the executable has a program header of `type`.
bool HasProgramHeader(const std::string& path, uint32_t type) {
  std::ifstream file(path, std::ios::binary);
  Elf64_Ehdr header{};
  file.read(reinterpret_cast<char*>(&header), sizeof(header));
  for (int i = 0; i < header.e_phnum; ++i) {
    Elf64_Phdr program{};
    file.seekg(static_cast<std::streamoff>(header.e_phoff + i * header.e_phentsize));
    file.read(reinterpret_cast<char*>(&program), sizeof(program));
    if (file && program.p_type == type) return true;
  }
  return false;
}

TEST(FastStart, FullyStaticExecutablesHaveNoDynamicLoader) {
#if !AG_FAST_START
  GTEST_SKIP() << "built with -DAG_FAST_START=OFF";
#endif
  EXPECT_TRUE(HasProgramHeader(std::string(AG_BIN_DIR) + "/ag-run", PT_INTERP));
  for (const char* tool : kFullyStaticTools) {
    const std::string path = std::string(AG_BIN_DIR) + "/" + tool;
    EXPECT_FALSE(HasProgramHeader(path, PT_INTERP)) << tool << " is linked dynamically";
    // Where its unwinder finds the sorted FDE table (common/no_frame_registry.cc).
    EXPECT_TRUE(HasProgramHeader(path, PT_GNU_EH_FRAME)) << tool;
    EXPECT_EQ(ElfType(path), ET_EXEC) << tool << " is position-independent";
  }
}

// The libraries that the dynamic loader reports loading (LD_DEBUG=files)
// while `command` runs, workers included, one per line.
std::string LoadedLibraries(const std::string& command) {
  const CommandResult run = RunProgram({"sh", "-c", "LD_DEBUG=files exec " + command});
  EXPECT_EQ(run.exit_code, 0) << command;
  std::string libraries;
  for (size_t at = run.err.find("file="); at != std::string::npos;
       at = run.err.find("file=", at + 1)) {
    libraries += run.err.substr(at, run.err.find_first_of(" \n", at) - at) + "\n";
  }
  return libraries;
}

// ag-run needs LCM only to publish: a run without --publish never loads it
// (nor glib behind it); with --publish it is loaded on first use and works.
TEST(FastStart, AgRunLoadsLcmOnlyWhenItPublishes) {
#if !AG_FAST_START || !defined(__x86_64__)
  GTEST_SKIP() << "LCM is loaded on first use in fast-start builds for x86-64 only";
#endif
  TempDir dir;
  const std::string run = std::string(AG_BIN_DIR) + "/ag-run --jobs 1 --store " + dir.File("s.db") +
                          " " + SourcePath("examples/two_rooms.png");
  const std::string quiet = LoadedLibraries(run);
  EXPECT_NE(quiet.find("libc.so"), std::string::npos) << quiet;
  EXPECT_EQ(quiet.find("liblcm"), std::string::npos) << quiet;
  EXPECT_EQ(quiet.find("libglib"), std::string::npos) << quiet;
  const std::string publishing = LoadedLibraries(run + " --force --publish --url memq://");
  EXPECT_NE(publishing.find("liblcm.so"), std::string::npos) << publishing;
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
