// Every place a number enters the executables, fed NaN, infinities and
// +-1e308: command-line flags, --set options, options files, manifest
// columns, map_server YAML keys, the osmAG anchor and the live tools'
// timeout. Each must give one line on stderr and a non-zero exit, never a
// crash or a hang, and leave the store as it was.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

// The spellings a user (or a YAML file) would use: not a number, an
// infinity, and a finite number far beyond any map. (The in-process tests of
// the option and YAML parsers cover +-inf, +-1e308 and -1 for every key.)
struct AbsurdNumber {
  std::string text;
  std::string yaml;
};
const AbsurdNumber kAbsurdNumbers[] = {{"nan", ".nan"}, {"-inf", "-.inf"}, {"1e308", "1e308"}};

// A store with the two-room example run through the pipeline, and the image
// with a YAML beside it, made once for all tests here.
class Fixture {
 public:
  static const Fixture& Get() {
    // An object, not a leaked pointer: its TempDir is removed at exit.
    static const Fixture fixture;
    return fixture;
  }
  std::string store() const { return dir_.File("s.db"); }
  std::string image() const { return dir_.File("two_rooms.png"); }
  const TempDir& dir() const { return dir_; }

 private:
  Fixture() {
    std::filesystem::copy_file(SourcePath("examples/two_rooms.png"), image());
    const CommandResult run = RunTool("ag-run", {"--store", store(), "--jobs", "1", image()});
    EXPECT_EQ(run.exit_code, 0) << run.err;
  }
  TempDir dir_;
};

// The logical content of a store, as sqlite3's .dump prints it.
std::string DumpStore(const std::string& store) {
  return RunProgram({"sqlite3", store, ".dump"}).out;
}

// One way a number reaches a tool: `argv(dir, value)` runs the tool with the
// number (files it needs go into `dir`).
struct NumberEntry {
  std::string name;
  std::string tool;
  std::function<std::vector<std::string>(const TempDir&, const AbsurdNumber&)> args;
};

std::ostream& operator<<(std::ostream& out, const NumberEntry& entry) { return out << entry.name; }

// An image with a map_server YAML beside it, `line` added to a valid YAML.
std::string ImageWithYaml(const TempDir& dir, const std::string& yaml) {
  std::filesystem::copy_file(Fixture::Get().image(), dir.File("map.png"),
                             std::filesystem::copy_options::overwrite_existing);
  WriteFile(dir.File("map.yaml"), "image: map.png\n" + yaml);
  return dir.File("map.png");
}

// ag-import of an image whose YAML holds the number between `before` and `after`.
NumberEntry YamlEntry(const std::string& name, const std::string& before,
                      const std::string& after) {
  return {name, "ag-import", [=](const TempDir& dir, const AbsurdNumber& n) {
            return std::vector<std::string>{"--store", dir.File("new.db"),
                                            ImageWithYaml(dir, before + n.yaml + after)};
          }};
}

// ag-export --format osmag with the number in the anchor flag `flag`.
NumberEntry AnchorEntry(const std::string& name, const std::string& flag) {
  return {name, "ag-export", [=](const TempDir& dir, const AbsurdNumber& n) {
            return std::vector<std::string>{
                "--store", Fixture::Get().store(), "--map",      "two_rooms", "--format", "osmag",
                "--out",   dir.File("map.osm"),    flag + n.text};
          }};
}

std::vector<NumberEntry> Entries() {
  const auto store = [] { return Fixture::Get().store(); };
  const auto image = [] { return Fixture::Get().image(); };
  return {
      {"import_resolution_flag", "ag-import",
       [=](const TempDir& dir, const AbsurdNumber& n) {
         return std::vector<std::string>{"--store", dir.File("new.db"), "--resolution=" + n.text,
                                         image()};
       }},
      {"import_set_resolution", "ag-import",
       [=](const TempDir& dir, const AbsurdNumber& n) {
         return std::vector<std::string>{"--store", dir.File("new.db"), "--set",
                                         "import.resolution_m=" + n.text, image()};
       }},
      {"stage_set_option", "ag-prune",
       [=](const TempDir&, const AbsurdNumber& n) {
         return std::vector<std::string>{"--store",   store(), "--map",
                                         "two_rooms", "--set", "prune.min_clearance_m=" + n.text};
       }},
      {"pipeline_options_file", "ag-pipeline",
       [=](const TempDir& dir, const AbsurdNumber& n) {
         WriteFile(dir.File("o.pbtxt"), "merge { min_area_m2: " + n.text + " }\n");
         return std::vector<std::string>{"--store",   store(),     "--map",
                                         "two_rooms", "--options", dir.File("o.pbtxt")};
       }},
      YamlEntry("yaml_resolution", "resolution: ", "\n"),
      YamlEntry("yaml_origin_x", "resolution: 0.05\norigin: [", ", 0, 0]\n"),
      YamlEntry("yaml_origin_yaw", "resolution: 0.05\norigin: [0, 0, ", "]\n"),
      YamlEntry("yaml_threshold", "resolution: 0.05\nfree_thresh: ", "\n"),
      AnchorEntry("export_anchor_lat", "--anchor-lat="),
      AnchorEntry("export_anchor_lon", "--anchor-lon="),
      {"listen_timeout", "ag-listen",
       [=](const TempDir&, const AbsurdNumber& n) {
         return std::vector<std::string>{"--url", "memq://", "--timeout=" + n.text};
       }},
      {"live_timeout", "ag-live",
       [=](const TempDir&, const AbsurdNumber& n) {
         return std::vector<std::string>{"--url", "memq://", "--store",
                                         ":memory:", "--timeout=" + n.text};
       }},
      {"run_manifest_column", "ag-run",
       [=](const TempDir& dir, const AbsurdNumber& n) {
         WriteFile(dir.File("maps.csv"), "path,cut.room_width_m\n" + image() + "," + n.text + "\n");
         return std::vector<std::string>{"--store", store(), dir.File("maps.csv")};
       }},
      {"run_set_option", "ag-run",
       [=](const TempDir&, const AbsurdNumber& n) {
         return std::vector<std::string>{"--store", store(), "--set",
                                         "clean.robot_width_m=" + n.text, image()};
       }},
      {"eval_gt_offset", "ag-eval",
       [=](const TempDir&, const AbsurdNumber& n) {
         return std::vector<std::string>{"--result", image(),       "--gt",
                                         image(),    "--gt-offset", n.text + ",0"};
       }},
  };
}

class AbsurdNumberTest : public ::testing::TestWithParam<NumberEntry> {};

TEST_P(AbsurdNumberTest, IsOneLineAndANonZeroExitAndTheStoreStaysAsItWas) {
  const std::string before = DumpStore(Fixture::Get().store());
  for (const AbsurdNumber& number : kAbsurdNumbers) {
    TempDir dir;
    // `timeout` turns an accepted number that makes a tool wait into a failure.
    std::vector<std::string> argv = {"timeout", "20", BinDir() + "/" + GetParam().tool};
    for (const std::string& arg : GetParam().args(dir, number)) argv.push_back(arg);
    const CommandResult result = RunProgram(argv);
    EXPECT_EQ(result.signal, 0) << number.text;
    EXPECT_TRUE(result.exit_code == 1 || result.exit_code == 2)
        << number.text << " exit " << result.exit_code << ": " << result.err;
    EXPECT_EQ(CountLines(result.err), 1) << number.text << ": " << result.err;
    EXPECT_EQ(result.err.rfind(GetParam().tool + ": ", 0), 0u) << number.text << ": " << result.err;
    EXPECT_FALSE(std::filesystem::exists(dir.File("new.db"))) << number.text;
    EXPECT_FALSE(std::filesystem::exists(dir.File("map.osm"))) << number.text;
  }
  EXPECT_EQ(DumpStore(Fixture::Get().store()), before);
}

INSTANTIATE_TEST_SUITE_P(EveryNumberSource, AbsurdNumberTest, ::testing::ValuesIn(Entries()),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace areagraph::testing
