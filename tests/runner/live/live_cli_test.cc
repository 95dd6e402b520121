// ag-live and ag-listen refuse bad flags, URLs and stores with one clear line
// and a non-zero exit, before any LCM traffic could start.
#include <gtest/gtest.h>

#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::RunTool;

void ExpectFailure(const std::string& tool, const std::vector<std::string>& args,
                   const std::string& message) {
  const testing::CommandResult result = RunTool(tool, args);
  EXPECT_NE(result.exit_code, 0) << tool << " " << result.out;
  EXPECT_EQ(testing::CountLines(result.err), 1) << result.err;
  EXPECT_NE(result.err.find(tool + ": " + message), std::string::npos) << result.err;
}

TEST(LiveCli, HelpDescribesTheTools) {
  const testing::CommandResult live = RunTool("ag-live", {"--help"});
  EXPECT_EQ(live.exit_code, 0);
  EXPECT_NE(live.out.find("channel MAP"), std::string::npos);
  EXPECT_NE(live.out.find("udpm://239.255.76.67:7667?ttl=0"), std::string::npos);
  EXPECT_NE(live.out.find("glibc.malloc.hugetlb=1"), std::string::npos);
  const testing::CommandResult listen = RunTool("ag-listen", {"--help"});
  EXPECT_EQ(listen.exit_code, 0);
  EXPECT_NE(listen.out.find("AREA_GRAPH"), std::string::npos);
}

TEST(LiveCli, RefusesUrlsThatLeaveTheHost) {
  for (const std::string tool : {"ag-live", "ag-listen"}) {
    ExpectFailure(tool, {"--url", "udpm://239.255.76.67:7667?ttl=1", "--store", ":memory:"},
                  "LCM URL 'udpm://239.255.76.67:7667?ttl=1' sets ttl=1, which would send "
                  "traffic beyond this host");
    ExpectFailure(tool, {"--url", "tcpq://192.0.2.1:7700", "--store", ":memory:"},
                  "LCM provider 'tcpq'");
  }
}

TEST(LiveCli, RefusesBadFlagsAndStores) {
  testing::TempDir dir;
  const std::string missing_dir_store = dir.File("no/such/dir/x.db");
  ExpectFailure("ag-live", {"--count", "-1"}, "--count must be 0 (no limit) or positive");
  ExpectFailure("ag-listen", {"--timeout", "-2"},
                "--timeout must be 0 (none) or a number of seconds up to 10000000");
  ExpectFailure("ag-live", {"--set", "cut.no_such_option=1"},
                "unknown option 'cut.no_such_option'");
  ExpectFailure("ag-live", {"--set", "import.max_pixels=0", "--store", ":memory:"},
                "import.max_pixels must be positive");
  ExpectFailure("ag-live", {"--store", missing_dir_store}, "cannot create store");
  ExpectFailure("ag-listen", {"--store", missing_dir_store}, "cannot create store");
  ExpectFailure("ag-live", {"--no-such-flag"}, "");
}

}  // namespace
}  // namespace areagraph
