// Every kind of bad input makes ag-import print one line on stderr and exit
// non-zero without creating or changing a store.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "tests/stages/import/import_test_util.h"
#include "tests/stages/import/test_png_writer.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::CommandResult;
using testing::RunTool;
using testing::TempDir;
using testing::WriteFile;

struct BadInput {
  std::string name;
  // Creates the input files in `dir` and returns the arguments (no --store).
  std::function<std::vector<std::string>(const TempDir& dir)> make;
  // Part of the expected error line.
  std::string message;
};

std::string ValidPngBytes() {
  TempDir dir;
  testing::WriteTwoRoomPng(dir.File("valid.png"));
  return testing::ReadFile(dir.File("valid.png"));
}

// A file named `name` holding `bytes`; returns {path}.
std::function<std::vector<std::string>(const TempDir&)> File(const std::string& name,
                                                             const std::string& bytes) {
  return [=](const TempDir& dir) {
    WriteFile(dir.File(name), bytes);
    return std::vector<std::string>{dir.File(name)};
  };
}

// A valid PNG (two_rooms.png) with `yaml` beside it as two_rooms.yaml, given
// as `arg` after `flags`.
std::function<std::vector<std::string>(const TempDir&)> WithYaml(
    const std::string& yaml, const std::string& arg = "two_rooms.yaml",
    std::vector<std::string> flags = {}) {
  return [=](const TempDir& dir) {
    WriteFile(dir.File("two_rooms.png"), ValidPngBytes());
    WriteFile(dir.File("two_rooms.yaml"), yaml);
    std::vector<std::string> args = flags;
    args.push_back(dir.File(arg));
    return args;
  };
}

// A valid PNG given with `flags`.
std::function<std::vector<std::string>(const TempDir&)> ValidWith(std::vector<std::string> flags) {
  return [=](const TempDir& dir) {
    WriteFile(dir.File("good.png"), ValidPngBytes());
    std::vector<std::string> args = flags;
    args.push_back(dir.File("good.png"));
    return args;
  };
}

std::vector<BadInput> BadInputs() {
  const std::string png = ValidPngBytes();
  return {
      {"missing file",
       [](const TempDir& dir) { return std::vector<std::string>{dir.File("absent.png")}; },
       "does not exist"},
      {"directory", [](const TempDir& dir) { return std::vector<std::string>{dir.path()}; },
       "is a directory"},
      {"empty file", File("empty.png", ""), "is empty"},
      {"PNG cut in the header", File("cut.png", png.substr(0, 20)), "no IHDR chunk"},
      {"PNG cut in the data", File("cut.png", png.substr(0, png.size() / 2)), "is truncated"},
      {"PNG with corrupt data",
       File("corrupt.png",
            png.substr(0, 40) + std::string(png.size() - 52, 'x') + png.substr(png.size() - 12)),
       "cannot decode image"},
      {"text file named .png", File("text.png", "this is not an image\n"),
       "is not an image that OpenCV can read"},
      {"0x0 PGM", File("zero.pgm", "P5\n0 0\n255\n"), "no pixels"},
      {"PGM cut short", File("short.pgm", "P5\n4 4\n255\nab"), "cannot decode image"},
      {"PNG 0 pixels wide", File("narrow.png", testing::HeaderOnlyPng(0, 5)), "has no pixels"},
      {"PNG decompression bomb", File("bomb.png", testing::HeaderOnlyPng(40000, 40000)),
       "40000x40000 pixels, more than import.max_pixels = 100000000"},
      {"PGM over a lowered pixel limit",
       [](const TempDir& dir) {
         WriteFile(dir.File("big.pgm"), "P5\n4 4\n255\n" + std::string(16, '\xff'));
         return std::vector<std::string>{"--set", "import.max_pixels=15", dir.File("big.pgm")};
       },
       "4x4 pixels, more than import.max_pixels = 15"},
      {"YAML malformed", WithYaml("image: two_rooms.png\nresolution: [0.05\n"), "malformed"},
      {"YAML beside the image malformed", WithYaml("resolution: : :\n", "two_rooms.png"),
       "malformed"},
      {"YAML without resolution", WithYaml("image: two_rooms.png\n"), "lacks 'resolution'"},
      {"YAML without image", WithYaml("resolution: 0.05\n"), "lacks 'image'"},
      {"YAML resolution 0", WithYaml("image: two_rooms.png\nresolution: 0\n"),
       "'resolution' must be a resolution in [0.0001, 1000]"},
      {"YAML resolution negative", WithYaml("image: two_rooms.png\nresolution: -0.05\n"),
       "'resolution' must be a resolution in [0.0001, 1000]"},
      {"YAML resolution NaN", WithYaml("image: two_rooms.png\nresolution: .nan\n"),
       "'resolution' must be finite"},
      {"YAML resolution absurd", WithYaml("image: two_rooms.png\nresolution: 1e9\n"),
       "'resolution' must be a resolution in [0.0001, 1000]"},
      {"YAML image missing", WithYaml("image: elsewhere.png\nresolution: 0.05\n"),
       "elsewhere.png' (named in"},
      {"YAML not a mapping", WithYaml("- a\n- b\n"), "expected keys"},
      {"YAML bad mode", WithYaml("image: two_rooms.png\nresolution: 0.05\nmode: x\n"),
       "'mode' must be trinary, scale or raw"},
      {"--resolution 0", ValidWith({"--resolution", "0"}), "--resolution must be a resolution"},
      {"--resolution negative", ValidWith({"--resolution=-0.05"}),
       "--resolution must be a resolution"},
      {"--resolution NaN", ValidWith({"--resolution", "nan"}), "--resolution"},
      {"--resolution huge", ValidWith({"--resolution", "1e9"}),
       "--resolution must be a resolution"},
      {"--resolution against the YAML",
       WithYaml("image: two_rooms.png\nresolution: 0.05\n", "two_rooms.png",
                {"--resolution", "0.1"}),
       "contradicts resolution 0.05"},
      {"import.resolution_m 0", ValidWith({"--set", "import.resolution_m=0"}),
       "import.resolution_m must be a resolution"},
      {"thresholds crossed", ValidWith({"--set", "import.occupied_max_grey=250"}),
       "must satisfy 0 <= occupied_max_grey < free_min_grey <= 255"},
      {"unknown option key", ValidWith({"--set", "import.nope=1"}), "unknown option"},
      {"missing options file", ValidWith({"--options", "/nonexistent/options.txt"}),
       "cannot read options file"},
      {"unknown flag", ValidWith({"--bogus"}), "bogus"},
  };
}

void ExpectOneErrorLine(const CommandResult& run, const BadInput& input) {
  EXPECT_NE(run.exit_code, 0) << input.name;
  EXPECT_EQ(run.signal, 0) << input.name;
  EXPECT_EQ(testing::CountLines(run.err), 1) << input.name << ":\n" << run.err;
  EXPECT_EQ(run.err.rfind("ag-import: ", 0), 0u) << input.name << ": " << run.err;
  EXPECT_NE(run.err.find(input.message), std::string::npos) << input.name << ": " << run.err;
  EXPECT_EQ(run.out, "") << input.name;
}

TEST(BadInputTest, NoStoreIsCreated) {
  for (const BadInput& input : BadInputs()) {
    TempDir dir;
    const std::string store = dir.File("store.db");
    std::vector<std::string> args = input.make(dir);
    args.insert(args.begin(), {"--store", store});
    ExpectOneErrorLine(RunTool("ag-import", args), input);
    for (const char* suffix : {"", "-wal", "-shm", "-journal"}) {
      EXPECT_FALSE(std::filesystem::exists(store + suffix)) << input.name << " made " << suffix;
    }
  }
}

TEST(BadInputTest, ExistingStoreIsUnchanged) {
  TempDir store_dir;
  const std::string store = store_dir.File("store.db");
  testing::WriteTwoRoomPng(store_dir.File("seed.png"));
  ASSERT_EQ(RunTool("ag-import", {"--store", store, store_dir.File("seed.png")}).exit_code, 0);
  const std::string before = testing::DumpStore(store);
  ASSERT_NE(before.find("seed"), std::string::npos);
  for (const BadInput& input : BadInputs()) {
    TempDir dir;
    std::vector<std::string> args = input.make(dir);
    args.insert(args.begin(), {"--store", store});
    ExpectOneErrorLine(RunTool("ag-import", args), input);
    EXPECT_EQ(testing::DumpStore(store), before) << input.name;
  }
}

// Separate because the line comes from ApplyOverride (stages/common): protobuf
// logs its own parse error on stderr before ours.
TEST(BadInputTest, UnparsableSetValueGivesOneLine) {
  TempDir dir;
  const std::vector<std::string> args = ValidWith({"--set", "import.free_min_grey=abc"})(dir);
  std::vector<std::string> with_store = {"--store", dir.File("store.db")};
  with_store.insert(with_store.end(), args.begin(), args.end());
  ExpectOneErrorLine(RunTool("ag-import", with_store),
                     {"--set with a bad value", nullptr, "expects a int32"});
  EXPECT_FALSE(std::filesystem::exists(dir.File("store.db")));
}

}  // namespace
}  // namespace areagraph
