// ArtifactStore::Verify: digests, encodings, heads and input keys.
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "store/artifact_store.h"
#include "tests/store/maintenance_helpers.h"
#include "tests/support/raw_sqlite.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

using testing::Artifact;

// A map through three stages; import's input is a file digest.
void WriteChain(ArtifactStore& store, const std::string& map_name, const std::string& prefix) {
  store.WriteArtifact(Artifact(map_name, "import", prefix + "-i", {"file-digest"}));
  store.WriteArtifact(Artifact(map_name, "clean", prefix + "-c", {prefix + "-i"}));
  store.WriteArtifact(Artifact(map_name, "voronoi", prefix + "-v", {prefix + "-c"}));
}

std::vector<VerifyProblem> VerifyFile(const std::string& path) {
  return OpenArtifactStore(path, StoreMode::kReadOnly)->Verify({"import"});
}

TEST(VerifyTest, CleanStoreHasNoProblemsAndReportsProgress) {
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  WriteChain(*store, "a", "a");
  WriteChain(*store, "b", "b");
  std::vector<std::pair<int64_t, int64_t>> calls;
  EXPECT_TRUE(store
                  ->Verify({"import"},
                           [&](int64_t done, int64_t total) { calls.emplace_back(done, total); })
                  .empty());
  ASSERT_EQ(calls.size(), 6u);
  for (size_t i = 0; i < calls.size(); ++i) {
    EXPECT_EQ(calls[i], std::make_pair(static_cast<int64_t>(i + 1), int64_t{6}));
  }
  EXPECT_TRUE(OpenArtifactStore(":memory:")->Verify({"import"}).empty());  // empty store
}

TEST(VerifyTest, CorruptedPayloadIsReported) {
  testing::TempDir dir;
  const std::string path = dir.File("store.db");
  WriteChain(*OpenArtifactStore(path), "lab", "k");
  testing::FlipPayloadByte(path, "k-c", 2);
  const std::vector<VerifyProblem> problems = VerifyFile(path);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].map_name, "lab");
  EXPECT_EQ(problems[0].stage, "clean");
  EXPECT_EQ(problems[0].cache_key, "k-c");
  EXPECT_NE(problems[0].problem.find("(corrupt); recompute it with ag-clean --force"),
            std::string::npos)
      << problems[0].problem;
}

TEST(VerifyTest, PayloadThatIsNotProtobufIsReported) {
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  NewArtifact artifact = Artifact("m", "import", "k", {"file"});
  artifact.payload = "\x0a\x7f short";  // a length beyond the end
  store->WriteArtifact(artifact);
  const std::vector<VerifyProblem> problems = store->Verify({"import"});
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].cache_key, "k");
  EXPECT_EQ(problems[0].problem, "payload is not protobuf wire format");
}

TEST(VerifyTest, MissingInputIsReportedExceptForImport) {
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  store->WriteArtifact(Artifact("m", "import", "k-i", {"digest-of-a-file"}));
  store->WriteArtifact(Artifact("m", "clean", "k-c", {"k-i"}));
  store->WriteArtifact(Artifact("m", "prune", "k-p", {"k-c", "gone-key-12345"}));
  // An artifact of another map does not count as this map's input.
  store->WriteArtifact(Artifact("other", "clean", "k-o", {"k-i"}));
  const std::vector<VerifyProblem> problems = store->Verify({"import"});
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[0].cache_key, "k-p");
  EXPECT_EQ(problems[0].problem, "input gone-key-123 is not an artifact of the map");
  EXPECT_EQ(problems[1].map_name, "other");
  EXPECT_EQ(problems[1].problem, "input k-i is not an artifact of the map");
}

TEST(VerifyTest, BrokenHeadsAreReported) {
  testing::TempDir dir;
  const std::string path = dir.File("store.db");
  WriteChain(*OpenArtifactStore(path), "lab", "k");
  // By hand, with foreign keys off (the raw connection's default).
  testing::ExecSql(path,
                   "UPDATE heads SET artifact_id = 999 WHERE stage = 'voronoi';"
                   "UPDATE heads SET artifact_id = (SELECT id FROM artifacts WHERE cache_key = "
                   "'k-i') WHERE stage = 'clean';");
  const std::vector<VerifyProblem> problems = VerifyFile(path);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[0].stage, "clean");
  EXPECT_EQ(problems[0].cache_key, "k-i");
  EXPECT_EQ(problems[0].problem, "head points at an artifact of stage import");
  EXPECT_EQ(problems[1].stage, "voronoi");
  EXPECT_EQ(problems[1].problem, "head points at no artifact");
}

TEST(VerifyTest, HandEditedRowIsReportedAndTheCheckGoesOn) {
  testing::TempDir dir;
  const std::string path = dir.File("store.db");
  WriteChain(*OpenArtifactStore(path), "lab", "k");
  testing::ExecSql(path, "UPDATE artifacts SET payload = 'text' WHERE cache_key = 'k-i'");
  testing::FlipPayloadByte(path, "k-v", 0);
  const std::vector<VerifyProblem> problems = VerifyFile(path);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[0].cache_key, "k-i");
  EXPECT_NE(problems[0].problem.find("payload holds TEXT where BLOB belongs"), std::string::npos)
      << problems[0].problem;
  EXPECT_EQ(problems[1].cache_key, "k-v");
}

// Many maps, so that the tables and indexes span several pages.
std::string StoreOfManyMaps(const testing::TempDir& dir) {
  const std::string path = dir.File("store.db");
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(path);
  for (int map = 0; map < 60; ++map) {
    WriteChain(*store, "map_" + std::to_string(map), "k" + std::to_string(map));
  }
  return path;
}

bool HasSqliteFinding(const std::vector<VerifyProblem>& problems) {
  for (const VerifyProblem& problem : problems) {
    if (problem.problem.rfind("SQLite: ", 0) == 0 && problem.map_name.empty()) return true;
  }
  return false;
}

// The case: an index page damaged, every payload intact. Both checks
// see it (quick_check reads the b-tree pages, only not the index contents).
TEST(VerifyTest, DamagedIndexPageIsFoundThoughEveryPayloadIsIntact) {
  testing::TempDir dir;
  const std::string path = StoreOfManyMaps(dir);
  testing::DamageRootPage(path, "artifacts_by_map_and_time", 512);
  for (const StructureCheck check : {StructureCheck::kFull, StructureCheck::kQuick}) {
    const std::vector<VerifyProblem> problems =
        OpenArtifactStore(path, StoreMode::kReadOnly)->Verify({"import"}, nullptr, check);
    std::string all;
    for (const VerifyProblem& problem : problems) all += problem.problem + "\n";
    EXPECT_TRUE(HasSqliteFinding(problems))
        << (check == StructureCheck::kFull ? "full" : "quick") << "\n"
        << all;
  }
}

// An index that disagrees with its table (an entry missing) is invisible to
// quick_check and to the payloads; integrity_check finds it.
TEST(VerifyTest, IndexOutOfStepWithItsTableIsFoundByTheFullCheck) {
  testing::TempDir dir;
  const std::string path = StoreOfManyMaps(dir);
  testing::ExecSql(path,
                   "PRAGMA writable_schema = ON;"
                   "UPDATE sqlite_master SET sql = replace(sql, '(map_id, created_at)',"
                   " '(map_id, created_at) WHERE 0') WHERE name = 'artifacts_by_map_and_time';");
  EXPECT_TRUE(HasSqliteFinding(OpenArtifactStore(path, StoreMode::kReadOnly)->Verify({"import"})));
  EXPECT_FALSE(HasSqliteFinding(OpenArtifactStore(path, StoreMode::kReadOnly)
                                    ->Verify({"import"}, nullptr, StructureCheck::kQuick)));
}

// Damage in the artifacts table itself stops the reading: a problem, not a throw.
TEST(VerifyTest, StoreTooDamagedToReadIsAProblemNotAnException) {
  testing::TempDir dir;
  const std::string path = StoreOfManyMaps(dir);
  testing::DamageRootPage(path, "artifacts", 512);
  std::vector<VerifyProblem> problems;
  EXPECT_NO_THROW(problems = VerifyFile(path));
  EXPECT_FALSE(problems.empty());
}

}  // namespace
}  // namespace areagraph
