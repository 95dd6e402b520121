// Damage beside the payloads, through the tools: a key flipped in its row
// (the stable ids that vanished), a summary changed by hand. Each
// must be an error, never a silent fallback or a clean verify.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "tests/support/raw_sqlite.h"
#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

class DamagedRowCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const CommandResult run =
        RunTool("ag-run", {"--store", store_, SourcePath("examples/two_rooms.png")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
  }

  // The match head's key and the merge key that follows it in its row.
  std::vector<std::string> MatchRow() const {
    return {QueryColumn(store_,
                        "SELECT a.cache_key FROM artifacts a JOIN heads h ON h.artifact_id = a.id"
                        " WHERE h.stage = 'match'")[0],
            QueryColumn(store_,
                        "SELECT a.input_keys FROM artifacts a JOIN heads h ON h.artifact_id = a.id"
                        " WHERE h.stage = 'match'")[0]};
  }

  void ExpectOneLineFailure(const CommandResult& run, const std::string& text) const {
    EXPECT_EQ(run.exit_code, 1) << run.out << run.err;
    EXPECT_EQ(CountLines(run.err), 1) << run.err;
    EXPECT_NE(run.err.find(text), std::string::npos) << run.err;
  }

  TempDir dir_;
  const std::string store_ = dir_.File("s.db");
};

// The case: one hex digit of the match artifact's key flipped in its
// row. verify --quick passed, ag-export wrote osmAG without stable ids (it
// fell back to the merge graph), and merge copied the row into a store that
// verified clean.
TEST_F(DamagedRowCliTest, FlippedKeyOfTheMatchHeadIsAnErrorEverywhere) {
  const std::vector<std::string> row = MatchRow();
  std::string flipped = row[0];
  flipped[7] = flipped[7] == 'a' ? 'b' : 'a';
  ReplaceOnceInFile(store_, row[0] + row[1], flipped + row[1]);

  const CommandResult verify = RunTool("ag-store", {"verify", "--store", store_, "--quick"});
  EXPECT_EQ(verify.exit_code, 1) << verify.out;
  EXPECT_NE(verify.out.find("row digest mismatch"), std::string::npos) << verify.out;

  const std::string osm = dir_.File("m.osm");
  ExpectOneLineFailure(RunTool("ag-export", {"--store", store_, "--map", "two_rooms", "--format",
                                             "osmag", "--out", osm}),
                       "damaged");
  EXPECT_FALSE(std::filesystem::exists(osm));

  const std::string merged = dir_.File("merged.db");
  ExpectOneLineFailure(RunTool("ag-store", {"merge", merged, store_}), "is damaged");
  EXPECT_FALSE(std::filesystem::exists(merged));
}

// A summary changed by hand showed in ag-inspect --history and passed verify
// and merge.
TEST_F(DamagedRowCliTest, ChangedSummaryIsFoundByVerifyInspectAndMerge) {
  ExecSql(store_, "UPDATE artifacts SET summary = '99 areas, 1 passage' WHERE stage = 'match'");
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"verify", "--store", store_},
        std::vector<std::string>{"verify", "--store", store_, "--quick"}}) {
    const CommandResult verify = RunTool("ag-store", args);
    EXPECT_EQ(verify.exit_code, 1) << verify.out;
    EXPECT_NE(verify.out.find("two_rooms match"), std::string::npos) << verify.out;
  }
  const CommandResult history =
      RunTool("ag-inspect", {"--store", store_, "--history", "two_rooms"});
  EXPECT_EQ(history.out.find("99 areas"), std::string::npos) << history.out;
  ExpectOneLineFailure(history, "row digest mismatch");
  ExpectOneLineFailure(RunTool("ag-store", {"merge", dir_.File("merged.db"), store_}),
                       "is damaged");
}

}  // namespace
}  // namespace areagraph::testing
