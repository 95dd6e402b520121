// Every executable that writes a file, pointed at every kind of target: a
// link to a file, a FIFO, a private device node, a link
// to /dev/full, a folder, standard output ("-"), and a disk that is full.
// Every executable that prints a report, with standard output on /dev/full.
// Nothing that is not a regular file may be replaced, and every failure is
// one line on stderr with a non-zero exit.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

// A store with the whole pipeline of examples/two_rooms.png and a label
// image of it (a ground truth for ag-eval), made once for all tests here.
class PipelineStore {
 public:
  static const PipelineStore& Get() {
    // An object, not a leaked pointer: its TempDir is removed at exit.
    static const PipelineStore store;
    return store;
  }
  std::string store() const { return dir_.File("s.db"); }
  std::string labels() const { return dir_.File("labels.png"); }

 private:
  PipelineStore() {
    const CommandResult run = RunTool(
        "ag-run", {"--store", store(), "--jobs", "1", SourcePath("examples/two_rooms.png")});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    const CommandResult exported = RunTool("ag-export", {"--store", store(), "--map", "two_rooms",
                                                         "--format", "labels", "--out", labels()});
    EXPECT_EQ(exported.exit_code, 0) << exported.err;
  }
  TempDir dir_;
};

// One way of making a tool write a file. `target_in(dir)` is the path the
// tool will write inside `dir`; `args(dir)` runs it so.
struct WriterCase {
  std::string name;
  std::string tool;
  std::function<std::string(const std::string&)> target_in;
  std::function<std::vector<std::string>(const std::string&)> args;
  std::string magic;  // how the written bytes start
  bool takes_dash = true;
};

std::ostream& operator<<(std::ostream& out, const WriterCase& writer) { return out << writer.name; }

const std::string kPngMagic = "\x89PNG";

WriterCase ExportCase(const std::string& format, const std::string& magic) {
  return {"export_" + format, "ag-export", [](const std::string& dir) { return dir + "/out"; },
          [format](const std::string& dir) {
            return std::vector<std::string>{"--store",  PipelineStore::Get().store(),
                                            "--map",    "two_rooms",
                                            "--format", format,
                                            "--out",    dir + "/out"};
          },
          magic};
}

std::vector<WriterCase> Writers() {
  std::vector<WriterCase> writers = {ExportCase("labels", kPngMagic), ExportCase("geojson", "{"),
                                     ExportCase("osmag", "<?xml"), ExportCase("json", "{"),
                                     ExportCase("html", "<!DOCTYPE html>")};
  writers.push_back({"render", "ag-render", [](const std::string& dir) { return dir + "/out"; },
                     [](const std::string& dir) {
                       return std::vector<std::string>{"--store", PipelineStore::Get().store(),
                                                       "--map",   "two_rooms",
                                                       "--stage", "prune",
                                                       "--out",   dir + "/out"};
                     },
                     kPngMagic});
  writers.push_back(
      {"eval_gt_picture", "ag-eval", [](const std::string& dir) { return dir + "/out"; },
       [](const std::string& dir) {
         return std::vector<std::string>{"--gt",         PipelineStore::Get().labels(),
                                         "--gt-style",   "labels",
                                         "--gt-picture", dir + "/out"};
       },
       kPngMagic});
  writers.push_back({"make_example_maps", "ag-make-example-maps",
                     [](const std::string& dir) { return dir + "/two_rooms.png"; },
                     [](const std::string& dir) {
                       return std::vector<std::string>{"--out", dir};
                     },
                     kPngMagic, /*takes_dash=*/false});
  writers.push_back({"make_collection", "ag-make-collection",
                     [](const std::string& dir) {
                       std::filesystem::create_directories(dir + "/000");
                       return dir + "/000/map_00000.png";
                     },
                     [](const std::string& dir) {
                       return std::vector<std::string>{"--count", "1", dir};
                     },
                     kPngMagic, /*takes_dash=*/false});
  return writers;
}

bool IsLink(const std::string& path) { return std::filesystem::is_symlink(path); }

void ExpectOneLineFailure(const CommandResult& result, const std::string& needle) {
  EXPECT_EQ(result.signal, 0) << "killed by a signal";
  EXPECT_NE(result.exit_code, 0);
  EXPECT_EQ(CountLines(result.err), 1) << result.err;
  EXPECT_NE(result.err.find(needle), std::string::npos) << result.err;
}

class OutputTargetsTest : public ::testing::TestWithParam<WriterCase> {
 protected:
  CommandResult Run() const { return RunTool(GetParam().tool, GetParam().args(dir_.path())); }
  std::string Target() const { return GetParam().target_in(dir_.path()); }
  bool StartsWithMagic(const std::string& bytes) const {
    return bytes.compare(0, GetParam().magic.size(), GetParam().magic) == 0;
  }
  TempDir dir_;
  TempDir elsewhere_;
};

TEST_P(OutputTargetsTest, LinkToAFileStaysALinkAndItsFileIsWritten) {
  const std::string real = elsewhere_.File("real");
  WriteFile(real, "old");
  std::filesystem::create_symlink(real, Target());
  const CommandResult result = Run();
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(IsLink(Target()));
  EXPECT_TRUE(StartsWithMagic(ReadFile(real)));
}

TEST_P(OutputTargetsTest, FifoIsWrittenIntoAndStaysAFifo) {
  ASSERT_EQ(::mkfifo(Target().c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = ReadFile(Target()); });
  const CommandResult result = Run();
  reader.join();
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(std::filesystem::is_fifo(Target()));
  EXPECT_TRUE(StartsWithMagic(received));
}

TEST_P(OutputTargetsTest, PrivateDeviceNodeStaysADevice) {
  if (::mknod(Target().c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0) {
    GTEST_SKIP() << "mknod needs CAP_MKNOD; links to /dev/null are covered";
  }
  const CommandResult result = Run();
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(std::filesystem::is_character_file(Target()));
}

TEST_P(OutputTargetsTest, LinkToDevFullSaysNoSpace) {
  std::filesystem::create_symlink("/dev/full", Target());
  ExpectOneLineFailure(Run(), "no space left on device");
  EXPECT_TRUE(IsLink(Target()));
  EXPECT_TRUE(std::filesystem::is_character_file("/dev/full"));
}

TEST_P(OutputTargetsTest, FolderIsRefused) {
  std::filesystem::create_directories(Target());
  ExpectOneLineFailure(Run(), "it is a folder");
  EXPECT_TRUE(std::filesystem::is_directory(Target()));
}

// A 64 KiB tmpfs filled up, in a mount namespace of its own: the write fails
// with ENOSPC, the old file is still whole and no temporary file is left.
TEST_P(OutputTargetsTest, FullDiskKeepsTheOldFile) {
  const std::string disk = dir_.File("disk");
  std::filesystem::create_directory(disk);
  const std::string target = GetParam().target_in(disk);
  std::string command = "exec '" + BinDir() + "/" + GetParam().tool + "'";
  for (const std::string& arg : GetParam().args(disk)) command += " '" + arg + "'";
  const std::string script = "mount -t tmpfs -o size=64k tmpfs '" + disk +
                             "' 2>/dev/null || exit 77\n" + "mkdir -p \"$(dirname '" + target +
                             "')\"; printf old > '" + target + "'\n" + "cat /dev/zero > '" + disk +
                             "/filler' 2>/dev/null\n" + "(" + command + ") > /dev/null; code=$?\n" +
                             "cat '" + target + "'; echo; find '" + disk +
                             "' -name '.*tmp' | wc -l; exit $code\n";
  const CommandResult result = RunProgram({"unshare", "-m", "sh", "-c", script});
  if (result.exit_code == 77) GTEST_SKIP() << "cannot mount a tmpfs here (needs root)";
  ExpectOneLineFailure(result, "no space left on device");
  EXPECT_EQ(result.out, "old\n0\n");
}

INSTANTIATE_TEST_SUITE_P(EveryWriter, OutputTargetsTest, ::testing::ValuesIn(Writers()),
                         [](const auto& info) { return info.param.name; });

// The generators write into a folder and have no single --out.
std::vector<WriterCase> WritersTakingDash() {
  std::vector<WriterCase> writers;
  for (const WriterCase& writer : Writers()) {
    if (writer.takes_dash) writers.push_back(writer);
  }
  return writers;
}

using DashOutputTest = OutputTargetsTest;

TEST_P(DashOutputTest, DashIsStandardOutput) {
  std::vector<std::string> args = GetParam().args(dir_.path());
  std::replace(args.begin(), args.end(), GetParam().target_in(dir_.path()), std::string("-"));
  const CommandResult result = RunTool(GetParam().tool, args);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(StartsWithMagic(result.out)) << result.out.substr(0, 40);
  EXPECT_FALSE(std::filesystem::exists(dir_.File("-")));
}

INSTANTIATE_TEST_SUITE_P(EveryWriter, DashOutputTest, ::testing::ValuesIn(WritersTakingDash()),
                         [](const auto& info) { return info.param.name; });

// Every executable that reports on standard output, with it on /dev/full.
// Arguments name the shared store as {store}, its label image as {labels}
// and a fresh folder as {tmp}: the list is made when tests are listed, before
// any store exists.
struct ReporterCase {
  std::string name;
  std::vector<std::string> argv;  // the tool first
};

std::ostream& operator<<(std::ostream& out, const ReporterCase& reporter) {
  return out << reporter.name;
}

std::vector<ReporterCase> Reporters() {
  const std::vector<std::string> map = {"--store", "{store}", "--map", "two_rooms"};
  const auto with_map = [&](const std::string& tool, std::vector<std::string> extra) {
    std::vector<std::string> argv = {tool};
    argv.insert(argv.end(), map.begin(), map.end());
    argv.insert(argv.end(), extra.begin(), extra.end());
    return argv;
  };
  std::vector<ReporterCase> reporters;
  for (const char* stage : {"clean", "voronoi", "prune", "cut", "merge", "pipeline"}) {
    reporters.push_back({stage, with_map(std::string("ag-") + stage, {})});
  }
  const std::string image = SourcePath("examples/two_rooms.png");
  reporters.push_back({"import", {"ag-import", "--store", "{store}", image}});
  reporters.push_back({"run", {"ag-run", "--store", "{store}", "--jobs", "1", image}});
  reporters.push_back(
      {"run_json", {"ag-run", "--store", "{store}", "--jobs", "1", "--json", image}});
  reporters.push_back({"inspect_maps", {"ag-inspect", "--store", "{store}"}});
  reporters.push_back({"inspect_artifacts", with_map("ag-inspect", {})});
  reporters.push_back({"inspect_summary", with_map("ag-inspect", {"--stage", "merge"})});
  reporters.push_back({"inspect_json", with_map("ag-inspect", {"--stage", "merge", "--json"})});
  reporters.push_back({"inspect_failures", {"ag-inspect", "--store", "{store}", "--failures"}});
  reporters.push_back({"store_verify", {"ag-store", "verify", "--store", "{store}"}});
  reporters.push_back({"store_failures", {"ag-store", "failures", "--store", "{store}", "--json"}});
  reporters.push_back({"store_merge", {"ag-store", "merge", "{tmp}/merged.db", "{store}"}});
  reporters.push_back({"eval", {"ag-eval", "--result", "{labels}", "--gt", "{labels}"}});
  reporters.push_back(
      {"eval_json", {"ag-eval", "--result", "{labels}", "--gt", "{labels}", "--json"}});
  reporters.push_back({"render", with_map("ag-render", {"--out", "{tmp}/render.png"})});
  reporters.push_back({"make_example_maps", {"ag-make-example-maps", "--out", "{tmp}"}});
  reporters.push_back({"make_collection", {"ag-make-collection", "--count", "1", "{tmp}"}});
  reporters.push_back({"help", {"ag-inspect", "--help"}});
  reporters.push_back({"version", {"ag-run", "--version"}});
  return reporters;
}

std::string Substituted(std::string arg, const std::string& tmp) {
  for (const auto& [name, value] :
       {std::pair<std::string, std::string>{"{store}", PipelineStore::Get().store()},
        {"{labels}", PipelineStore::Get().labels()},
        {"{tmp}", tmp}}) {
    const size_t at = arg.find(name);
    if (at != std::string::npos) arg.replace(at, name.size(), value);
  }
  return arg;
}

class FullStandardOutputTest : public ::testing::TestWithParam<ReporterCase> {};

// The last line on stderr says what happened (ag-run's per-map lines come first).
TEST_P(FullStandardOutputTest, ReportLostToAFullDiskIsAnError) {
  TempDir tmp;
  std::vector<std::string> argv;
  for (const std::string& arg : GetParam().argv) argv.push_back(Substituted(arg, tmp.path()));
  argv[0] = BinDir() + "/" + argv[0];
  const CommandResult result = RunProgramWithStdout(argv, "/dev/full");
  EXPECT_EQ(result.signal, 0);
  EXPECT_EQ(result.exit_code, 1) << result.err;
  const std::string expected = "cannot write to standard output: no space left on device\n";
  ASSERT_GE(result.err.size(), expected.size()) << result.err;
  EXPECT_EQ(result.err.substr(result.err.size() - expected.size()), expected) << result.err;
}

INSTANTIATE_TEST_SUITE_P(EveryReporter, FullStandardOutputTest, ::testing::ValuesIn(Reporters()),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace areagraph::testing
