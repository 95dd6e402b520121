// examples/lcm_subscriber/area_graph_subscriber.py, with classes from
// `lcm-gen -p`, prints exactly what the C++ example prints for the same
// graphs from ag-run --publish: a small one (one datagram) and, with
// ../shared/data, lab_b, whose graph (about 90 KB) LCM sends in fragments.
// Everything runs inside `unshare -n` with multicast routed on loopback.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

TEST(PythonLcmSubscriber, PrintsWhatTheCppExamplePrints) {
  if (RunProgram({"unshare", "-n", "true"}).exit_code != 0) {
    GTEST_SKIP() << "unshare -n is not permitted here";
  }
  TempDir dir;
  const std::string d = dir.path(), bin = AG_BIN_DIR;
  const CommandResult generate =
      RunProgram({"lcm-gen", "-p", "--ppath", d + "/types", SourcePath("proto/area_graph_t.lcm")});
  ASSERT_EQ(generate.exit_code, 0) << generate.err;
  std::string maps = SourcePath("examples/two_rooms.png");
  int count = 1;
  if (HaveSharedData()) {
    maps += " " + SharedDataPath("areagraph/input/lab_b.png");
    count = 2;
  }
  const std::string n = std::to_string(count);
  const std::string script =
      "ip link set lo up && ip route add 224.0.0.0/4 dev lo || exit 90\n"
      "D=" +
      d + "\n" + bin + "/area_graph_subscriber 'udpm://239.255.76.67:7667?ttl=0' " + n +
      " >$D/cpp.out 2>$D/cpp.err &\n"
      "C=$!\n"
      "/usr/bin/python3 " +
      SourcePath("examples/lcm_subscriber/area_graph_subscriber.py") +
      " --types $D/types --count " + n +
      " --timeout 240 >$D/py.out 2>$D/py.err &\n"
      "P=$!\n"
      "i=0; until grep -q listening $D/cpp.err && grep -q listening $D/py.err; do\n"
      "  i=$((i+1)); [ $i -gt 300 ] && { kill $C $P; exit 91; }; sleep 0.1; done\n" +
      bin + "/ag-run --store $D/s.db --jobs 1 --publish " + maps +
      " >$D/run.out 2>&1 || exit 92\n"
      "wait $C || exit 93\n"
      "wait $P || exit 94\n";
  const CommandResult result = RunProgram({"unshare", "-n", "sh", "-c", script});
  ASSERT_EQ(result.exit_code, 0) << result.err << ReadFile(d + "/py.err")
                                 << ReadFile(d + "/cpp.err") << ReadFile(d + "/run.out");
  const std::string python = ReadFile(d + "/py.out"), cpp = ReadFile(d + "/cpp.out");
  EXPECT_EQ(python, cpp);
  EXPECT_EQ(python.rfind("AREA_GRAPH: map 'two_rooms', 2 areas, 1 passages (key ", 0), 0u)
      << python;
  if (count == 2) {
    EXPECT_NE(python.find("AREA_GRAPH: map 'lab_b', "), std::string::npos) << python;
  }
}

TEST(PythonLcmSubscriber, MissingTypesAreOneLine) {
  TempDir dir;
  const CommandResult run = RunProgram(
      {"/usr/bin/python3", SourcePath("examples/lcm_subscriber/area_graph_subscriber.py"),
       "--types", dir.File("none"), "--count", "1"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(CountLines(run.err), 1) << run.err;
  EXPECT_NE(run.err.find("lcm-gen -p"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace areagraph::testing
