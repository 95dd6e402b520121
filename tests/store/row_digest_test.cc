// The row digest (schema 6): damage to the columns beside the payload (a
// key, inputs, options, the summary, the time, the map's name) is found by
// both verify checks, by every read of the row and by merge, as damage to a
// payload is. Older stores stay readable and are sealed when upgraded.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/error.h"
#include "store/artifact_store.h"
#include "store/digest.h"
#include "tests/store/maintenance_helpers.h"
#include "tests/support/raw_sqlite.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::Artifact;

// Keys as the stages make them: 64 hex digits.
std::string Key(const std::string& seed) { return Sha256Hex(seed); }

// A map of three stages with real-looking keys; returns the keys in order.
std::vector<std::string> WriteChain(ArtifactStore& store, const std::string& map_name) {
  const std::vector<std::string> keys = {Key(map_name + "i"), Key(map_name + "c"),
                                         Key(map_name + "v")};
  NewArtifact import = Artifact(map_name, "import", keys[0], {Key(map_name + "file")});
  import.options_text = "resolution_m: 0.05\n";
  import.summary_line = "40 x 30 cells";
  import.source_path = map_name + ".png";
  import.source_digest = Key(map_name + "file");
  store.WriteArtifact(import);
  NewArtifact clean = Artifact(map_name, "clean", keys[1], {keys[0]});
  clean.options_text = "robot_width_m: 0.4\n";
  clean.summary_line = "3 outliers removed";
  store.WriteArtifact(clean);
  NewArtifact voronoi = Artifact(map_name, "voronoi", keys[2], {keys[1]});
  voronoi.summary_line = "28 sites";
  store.WriteArtifact(voronoi);
  return keys;
}

bool HasProblem(const std::vector<VerifyProblem>& problems, const std::string& key,
                const std::string& text) {
  for (const VerifyProblem& problem : problems) {
    if (problem.cache_key == key && problem.problem.find(text) != std::string::npos) return true;
  }
  return false;
}

std::vector<VerifyProblem> VerifyFile(const std::string& path, StructureCheck check) {
  return OpenArtifactStore(path, StoreMode::kReadOnly)->Verify({"import"}, nullptr, check);
}

std::string MergeError(const std::string& into, const std::string& from) {
  return testing::ErrorOf<StoreError>([&] { OpenArtifactStore(into)->MergeFrom(from); });
}

class RowDigestTest : public ::testing::Test {
 protected:
  void SetUp() override { keys_ = WriteChain(*OpenArtifactStore(path_), "lab"); }

  testing::TempDir dir_;
  const std::string path_ = dir_.File("s.db");
  std::vector<std::string> keys_;
};

// The "99 areas for a graph of 28": a summary and options changed
// by hand passed verify, merge and every read.
TEST_F(RowDigestTest, ChangedSummaryOrOptionsIsFoundByVerifyReadsAndMerge) {
  testing::ExecSql(
      path_, "UPDATE artifacts SET summary = '99 areas' WHERE cache_key = '" + keys_[1] + "'");
  testing::ExecSql(
      path_,
      "UPDATE artifacts SET options = 'robot_width_m: 9\n' WHERE cache_key = '" + keys_[0] + "'");
  for (const StructureCheck check : {StructureCheck::kFull, StructureCheck::kQuick}) {
    const std::vector<VerifyProblem> problems = VerifyFile(path_, check);
    EXPECT_TRUE(HasProblem(problems, keys_[1], "row digest mismatch"));
    EXPECT_TRUE(HasProblem(problems, keys_[0], "row digest mismatch"));
    EXPECT_FALSE(HasProblem(problems, keys_[2], ""));
  }
  const auto store = OpenArtifactStore(path_, StoreMode::kReadOnly);
  EXPECT_NE(testing::ErrorOf<StoreError>([&] {
              store->ReadArtifactSummaries("lab");
            }).find("is damaged (row digest mismatch"),
            std::string::npos);
  EXPECT_NE(testing::ErrorOf<StoreError>([&] {
              store->ReadHead("lab", "clean");
            }).find("ag-store verify --store " + path_),
            std::string::npos);
  EXPECT_TRUE(store->ReadHead("lab", "voronoi").has_value());  // the rest reads on

  const std::string into = dir_.File("into.db");
  const std::string error = MergeError(into, path_);
  EXPECT_NE(error.find("store '" + path_ + "' is damaged: artifact "), std::string::npos) << error;
  EXPECT_NE(error.find("has a damaged row (row digest mismatch"), std::string::npos) << error;
  EXPECT_NE(error.find("nothing was merged"), std::string::npos) << error;
  EXPECT_TRUE(OpenArtifactStore(into, StoreMode::kReadOnly)->ReadAllMaps().empty());
}

// The case: one hex digit of a key flipped in the table's row, as
// bit rot would do it. The unique index still holds the old key, so SQLite's
// quick check sees nothing and lookups by the key miss the row.
TEST_F(RowDigestTest, KeyFlippedInItsRowIsFoundByTheQuickCheckAndRefusedByMerge) {
  std::string flipped = keys_[1];
  flipped[10] = flipped[10] == 'a' ? 'b' : 'a';
  // The row's key is followed by its input keys; the index's by a row id.
  testing::ReplaceOnceInFile(path_, keys_[1] + keys_[0], flipped + keys_[0]);

  const std::vector<VerifyProblem> quick = VerifyFile(path_, StructureCheck::kQuick);
  EXPECT_TRUE(HasProblem(quick, flipped, "row digest mismatch"));
  const std::vector<VerifyProblem> full = VerifyFile(path_, StructureCheck::kFull);
  EXPECT_TRUE(HasProblem(full, flipped, "row digest mismatch"));

  const std::string error = MergeError(dir_.File("into.db"), path_);
  EXPECT_NE(error.find("is damaged"), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

// Damage only the full check sees (an index out of step with its table) is
// refused by merge, which looks rows up through the indexes.
TEST_F(RowDigestTest, MergeRefusesIndexDamageThatOnlyTheFullCheckSees) {
  testing::ExecSql(path_,
                   "PRAGMA writable_schema = ON;"
                   "UPDATE sqlite_master SET sql = replace(sql, '(map_id, created_at)',"
                   " '(map_id, created_at) WHERE 0') WHERE name = 'artifacts_by_map_and_time';");
  ASSERT_TRUE(VerifyFile(path_, StructureCheck::kQuick).empty());
  ASSERT_FALSE(VerifyFile(path_, StructureCheck::kFull).empty());
  const std::string error = MergeError(dir_.File("into.db"), path_);
  EXPECT_NE(error.find("store '" + path_ + "' is damaged (SQLite: "), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

// A map row renamed in the file (its name index keeps the old name) made
// merge fail on "NOT NULL constraint failed"; now it is refused by name.
TEST_F(RowDigestTest, MapRenamedInItsRowIsRefusedByMergeInOneClearLine) {
  // The row's name is followed by its source path; the name index's by a row id.
  testing::ReplaceOnceInFile(path_, "lablab.png", "lbblab.png");
  const std::string error = MergeError(dir_.File("into.db"), path_);
  EXPECT_NE(error.find("store '" + path_ + "' is damaged"), std::string::npos) << error;
  EXPECT_EQ(error.find("NOT NULL"), std::string::npos) << error;
}

// A store of schema 5 is read as it is (no digests to check) and sealed
// when opened for writing: from then on its rows are covered.
TEST_F(RowDigestTest, Schema5StoreIsReadAndSealedWhenUpgraded) {
  testing::RewriteAsSchema5(path_);
  EXPECT_TRUE(VerifyFile(path_, StructureCheck::kFull).empty());
  EXPECT_EQ(testing::QueryColumn(path_, "PRAGMA user_version")[0], "5");
  EXPECT_EQ(OpenArtifactStore(path_, StoreMode::kReadOnly)->ReadHead("lab", "clean")->summary_line,
            "3 outliers removed");

  OpenArtifactStore(path_);  // upgrades
  EXPECT_EQ(testing::QueryColumn(path_, "PRAGMA user_version")[0],
            std::to_string(kStoreSchemaVersion));
  EXPECT_EQ(testing::QueryColumn(path_, "SELECT count(*) FROM artifacts WHERE row_digest = ''")[0],
            "0");
  EXPECT_TRUE(VerifyFile(path_, StructureCheck::kFull).empty());
  testing::ExecSql(path_,
                   "UPDATE artifacts SET summary = 'x' WHERE cache_key = '" + keys_[2] + "'");
  EXPECT_TRUE(HasProblem(VerifyFile(path_, StructureCheck::kQuick), keys_[2], "row digest"));
}

// Rows merged from a store of schema 5 get their digests in the output.
TEST_F(RowDigestTest, RowsMergedFromASchema5StoreAreSealed) {
  testing::RewriteAsSchema5(path_);
  const std::string into = dir_.File("into.db");
  EXPECT_EQ(MergeError(into, path_), "");
  EXPECT_EQ(testing::QueryColumn(into, "SELECT count(*) FROM artifacts WHERE row_digest = ''")[0],
            "0");
  EXPECT_TRUE(VerifyFile(into, StructureCheck::kFull).empty());
  EXPECT_EQ(OpenArtifactStore(into, StoreMode::kReadOnly)->ReadHead("lab", "clean")->summary_line,
            "3 outliers removed");
}

}  // namespace
}  // namespace areagraph
