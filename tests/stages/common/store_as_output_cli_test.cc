// A tool that reads a store and writes a file must never write over that
// store or the files SQLite keeps beside it, under any name: the store's own
// path, another spelling of it, an absolute path, a symbolic link to it, or
// its -wal and -shm. Each is refused with one line and the store is left
// byte for byte as it was.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

// The whole pipeline of examples/two_rooms.png in one store, made once and
// copied into each test's folder.
const std::string& PipelineStoreBytes() {
  static const std::string* bytes = [] {
    TempDir dir;
    const CommandResult run = RunTool("ag-run", {"--store", dir.File("s.db"), "--jobs", "1",
                                                 SourcePath("examples/two_rooms.png")});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return new std::string(ReadFile(dir.File("s.db")));
  }();
  return *bytes;
}

struct OverwriteCase {
  std::string name;
  std::vector<std::string> tool_args;  // the tool and its flags up to --out
  std::string out;                     // relative to the store's folder, or ABS/... for absolute
  std::string link_to;                 // when set: `out` is made a symbolic link to this
  std::string expected_reason;
};

std::ostream& operator<<(std::ostream& out, const OverwriteCase& c) { return out << c.name; }

const std::vector<std::string> kExportJson = {"ag-export", "--store",  "s.db", "--map",
                                              "two_rooms", "--format", "json"};
const std::vector<std::string> kExportLabels = {"ag-export", "--store",  "s.db",  "--map",
                                                "two_rooms", "--format", "labels"};
const std::vector<std::string> kExportHtml = {"ag-export", "--store",  "s.db", "--map",
                                              "two_rooms", "--format", "html"};
const std::vector<std::string> kRender = {"ag-render", "--store", "s.db", "--map",
                                          "two_rooms", "--stage", "merge"};

std::vector<OverwriteCase> Cases() {
  return {
      {"export_json_same_name", kExportJson, "s.db", "", "it is the store"},
      {"export_json_dot_slash", kExportJson, "./s.db", "", "it is the store"},
      {"export_json_absolute", kExportJson, "ABS/s.db", "", "it is the store"},
      {"export_json_through_a_link", kExportJson, "link.json", "s.db", "it is the store"},
      {"export_json_parent_spelling", kExportJson, "sub/../s.db", "", "it is the store"},
      {"export_json_wal", kExportJson, "s.db-wal", "", "write-ahead log of the store"},
      {"export_json_shm", kExportJson, "s.db-shm", "", "shared-memory file of the store"},
      {"export_labels_same_name", kExportLabels, "s.db", "", "it is the store"},
      {"export_html_same_name", kExportHtml, "./s.db", "", "it is the store"},
      {"render_same_name", kRender, "s.db", "", "it is the store"},
      {"render_absolute", kRender, "ABS/s.db", "", "it is the store"},
      {"render_through_a_link", kRender, "picture.png", "s.db", "it is the store"},
  };
}

class StoreAsOutputTest : public ::testing::TestWithParam<OverwriteCase> {};

TEST_P(StoreAsOutputTest, IsRefusedAndTheStoreStaysAsItWas) {
  const OverwriteCase& c = GetParam();
  TempDir dir;
  std::filesystem::create_directory(dir.File("sub"));
  WriteFile(dir.File("s.db"), PipelineStoreBytes());
  if (!c.link_to.empty()) std::filesystem::create_symlink(c.link_to, dir.File(c.out));
  std::string out = c.out;
  if (out.rfind("ABS/", 0) == 0) out = dir.path() + out.substr(3);
  // Run inside the store's folder, so that relative spellings mean what they say.
  std::vector<std::string> argv = {"env", "-C", dir.path(), BinDir() + "/" + c.tool_args[0]};
  argv.insert(argv.end(), c.tool_args.begin() + 1, c.tool_args.end());
  argv.insert(argv.end(), {"--out", out});
  const CommandResult result = RunProgram(argv);
  EXPECT_EQ(result.signal, 0);
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_EQ(CountLines(result.err), 1) << result.err;
  EXPECT_NE(result.err.find(c.expected_reason), std::string::npos) << result.err;
  EXPECT_TRUE(ReadFile(dir.File("s.db")) == PipelineStoreBytes()) << "the store changed";
  if (!c.link_to.empty()) EXPECT_TRUE(std::filesystem::is_symlink(dir.File(c.out)));
  const CommandResult verify = RunTool("ag-store", {"verify", "--store", dir.File("s.db")});
  EXPECT_EQ(verify.exit_code, 0) << verify.out << verify.err;
}

INSTANTIATE_TEST_SUITE_P(EveryWay, StoreAsOutputTest, ::testing::ValuesIn(Cases()),
                         [](const auto& info) { return info.param.name; });

// Another file beside the store is still written: the guard is about the
// store's own files only.
TEST(StoreAsOutput, AFileBesideTheStoreIsWritten) {
  TempDir dir;
  WriteFile(dir.File("s.db"), PipelineStoreBytes());
  const CommandResult result =
      RunTool("ag-export", {"--store", dir.File("s.db"), "--map", "two_rooms", "--format", "json",
                            "--out", dir.File("s.db.json")});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(ReadFile(dir.File("s.db.json")).substr(0, 1), "{");
}

}  // namespace
}  // namespace areagraph::testing
