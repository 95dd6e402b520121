// examples/cluster's Slurm scripts on a real Slurm: a one-node cluster on
// localhost (tools/slurm-local.sh) runs the 36 maps of areagraph/ and
// RobotMap plus a bad map as a 4-shard job array and the index job (and the
// merge job), and a shard task cancelled mid-run is queued again, resumes
// from its store and is indexed again.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <regex>
#include <thread>

#include "runner/run/shard.h"
#include "store/collection_index.h"
#include "tests/examples/cluster/local_slurm_cluster.h"
#include "tests/support/raw_sqlite.h"

namespace areagraph::testing {
namespace {

// Heads per map after a whole run: import, clean, voronoi, prune, cut, merge, match.
constexpr int kStagesPerMap = 7;

namespace fs = std::filesystem;

constexpr int kShards = 4;
constexpr double kJobTimeoutS = 150;  // the whole collection takes about 25 s here

// The collection step's own time in its log: "collection: 0.42 s".
const std::regex kCollectionTime(R"((^|\n)collection: \d+\.\d\d s\n)");

// "map stage" of every recorded failure, sorted.
std::vector<std::string> Failures(const std::string& store) {
  return QueryColumn(store, "SELECT map_name || ' ' || stage FROM failures ORDER BY 1");
}

// Every job log under `stores`/logs, for the message of a failed expectation.
std::string Logs(const std::string& stores) {
  std::string text;
  if (!fs::is_directory(stores + "/logs")) return "(no logs)";
  for (const auto& file : fs::directory_iterator(stores + "/logs")) {
    text += "--- " + file.path().filename().string() + "\n" + ReadFile(file.path());
  }
  return text;
}

class SlurmClusterTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!HaveSharedData()) return;
    dir_ = std::make_unique<TempDir>();
    cluster_ = std::make_unique<LocalSlurmCluster>(dir_->File("slurm"));
    if (!cluster_->running()) return;
    const std::string maps = dir_->File("maps");
    fs::create_directories(maps + "/areagraph");
    fs::create_directories(maps + "/RobotMap");
    for (const auto& [from, to] : {std::pair{"areagraph/input", "areagraph"},
                                   std::pair{"maoris/RobotMap/Maps", "RobotMap"}}) {
      for (const auto& file : fs::directory_iterator(SharedDataPath(from))) {
        fs::copy_file(file.path(), maps + "/" + to + "/" + file.path().filename().string());
      }
    }
    WriteFile(maps + "/broken.png", "not an image at all");
    reference_ = RunTool("ag-run", {"--store", dir_->File("reference.db"), "--jobs", "2", maps});
  }

  static void TearDownTestSuite() {
    cluster_.reset();  // stops the daemons before their folder goes
    dir_.reset();
  }

  void SetUp() override {
    if (!HaveSharedData()) GTEST_SKIP() << "needs ../shared/data for the 36 maps";
    if (!cluster_->running()) {
      // Only a machine where the daemons cannot run may skip; CI sets
      // AG_REQUIRE_SLURM so that there a start that fails fails the test.
      const char* required = std::getenv("AG_REQUIRE_SLURM");
      if (!cluster_->unavailable() || (required != nullptr && std::string(required) == "1")) {
        FAIL() << cluster_->problem();
      }
      GTEST_SKIP() << "no Slurm on this machine: " << cluster_->problem();
    }
    ASSERT_EQ(reference_.exit_code, 1) << "the unsharded run must record broken.png\n"
                                       << reference_.err;
  }

  // Runs slurm-submit.sh for `tasks` (all when empty) of kShards shards.
  SubmittedCollection Submit(const std::string& stores, const std::string& tasks = "",
                             const std::vector<std::string>& env = {}) const {
    std::vector<std::string> argv = {"bash", SourcePath("examples/cluster/slurm-submit.sh"), maps(),
                                     stores, std::to_string(kShards)};
    if (!tasks.empty()) argv.push_back(tasks);
    const CommandResult submit = cluster_->Run(argv, dir_->path(), env);
    EXPECT_EQ(submit.exit_code, 0) << submit.err;
    const SubmittedCollection jobs = ParseSubmitted(submit.out);
    EXPECT_EQ(jobs.step, "index") << submit.out;
    return jobs;
  }

  // The log of the collection step.
  static std::string CollectionLog(const std::string& stores, const SubmittedCollection& jobs) {
    return ReadFile(stores + "/logs/" + jobs.step + "-job" + jobs.collection + ".out");
  }

  std::string maps() const { return dir_->File("maps"); }
  std::string reference() const { return dir_->File("reference.db"); }

  static std::unique_ptr<TempDir> dir_;
  static std::unique_ptr<LocalSlurmCluster> cluster_;
  static CommandResult reference_;
};

std::unique_ptr<TempDir> SlurmClusterTest::dir_;
std::unique_ptr<LocalSlurmCluster> SlurmClusterTest::cluster_;
CommandResult SlurmClusterTest::reference_;

TEST_F(SlurmClusterTest, ShardArrayAndIndexGiveTheHeadsOfOneRun) {
  const std::string stores = dir_->File("stores");
  const SubmittedCollection jobs = Submit(stores);
  ASSERT_FALSE(jobs.collection.empty());
  ASSERT_TRUE(cluster_->WaitUntilEnded({jobs.shards, jobs.collection}, kJobTimeoutS))
      << "the jobs did not end in " << kJobTimeoutS << " s\n"
      << Logs(stores);

  const auto tasks = cluster_->States(jobs.shards);
  ASSERT_EQ(tasks.size(), static_cast<size_t>(kShards));
  for (const auto& [task, state] : tasks) EXPECT_EQ(state, "COMPLETED None") << task;
  EXPECT_EQ(cluster_->States(jobs.collection).at(jobs.collection), "COMPLETED None")
      << Logs(stores);

  // Every shard did a share of the work and verified its store; the index
  // job timed itself.
  for (int shard = 0; shard < kShards; ++shard) {
    const std::string store = stores + "/shard-" + std::to_string(shard) + ".db";
    ASSERT_TRUE(fs::exists(store)) << store;
    EXPECT_FALSE(HeadDigests(store).empty()) << store;
    const std::string log =
        ReadFile(stores + "/logs/shard-" + std::to_string(shard) + "-job" + jobs.shards + ".out");
    EXPECT_NE(log.find("checked " + std::to_string(HeadDigests(store).size()) +
                       " artifacts: no problems"),
              std::string::npos)
        << log;
  }
  const std::string index_log = CollectionLog(stores, jobs);
  EXPECT_NE(
      index_log.find("indexed 4 shard stores (36 maps, " + std::to_string(36 * kStagesPerMap) +
                     " artifacts) into " + stores + "/collection.db"),
      std::string::npos)
      << index_log;
  EXPECT_TRUE(std::regex_search(index_log, kCollectionTime)) << index_log;
  EXPECT_NE(index_log.find("broken"), std::string::npos) << "the failures close the log";

  const std::string index = stores + "/collection.db";
  const std::vector<std::string> expected = HeadDigests(reference());
  ASSERT_EQ(expected.size(),
            static_cast<size_t>(36 * kStagesPerMap));  // 36 maps; broken.png has none
  EXPECT_EQ(StoreHeadDigests(index), expected);
  EXPECT_EQ(Failures(index), std::vector<std::string>{"broken import"});
  EXPECT_EQ(Failures(index), Failures(reference()));
  // Each map's export from the collection is the unsharded run's, byte for byte.
  for (const std::string& map : QueryColumn(reference(), "SELECT name FROM maps ORDER BY name")) {
    const CommandResult from_index =
        RunTool("ag-export", {"--store", index, "--map", map, "--format", "geojson", "--out", "-"});
    const CommandResult from_reference = RunTool(
        "ag-export", {"--store", reference(), "--map", map, "--format", "geojson", "--out", "-"});
    ASSERT_EQ(from_index.exit_code, 0) << from_index.err;
    EXPECT_EQ(from_index.out, from_reference.out) << map;
  }
  for (const std::vector<std::string>& shallow :
       std::vector<std::vector<std::string>>{{}, {"--shallow"}}) {
    std::vector<std::string> args = {"verify", "--store", index};
    args.insert(args.end(), shallow.begin(), shallow.end());
    EXPECT_EQ(RunTool("ag-store", args).out,
              "checked " + std::to_string(36 * kStagesPerMap) + " artifacts: no problems\n");
  }

  // The merge step, for those who want one file: on a copy of the shards.
  const std::string copy = dir_->File("stores-merge");
  fs::create_directories(copy + "/logs");
  for (int shard = 0; shard < kShards; ++shard) {
    const std::string name = "/shard-" + std::to_string(shard) + ".db";
    fs::copy_file(stores + name, copy + name);
  }
  const CommandResult merge =
      cluster_->Run({"sbatch", "--parsable", "--output=" + copy + "/logs/merge.out",
                     SourcePath("examples/cluster/slurm-merge.sbatch"), copy},
                    dir_->path());
  ASSERT_EQ(merge.exit_code, 0) << merge.err;
  const std::string merge_job = merge.out.substr(0, merge.out.find_first_of(";\n"));
  ASSERT_TRUE(cluster_->WaitUntilEnded({merge_job}, kJobTimeoutS)) << Logs(copy);
  const std::string merge_log = ReadFile(copy + "/logs/merge.out");
  EXPECT_NE(
      merge_log.find("checked " + std::to_string(36 * kStagesPerMap) + " artifacts: no problems"),
      std::string::npos)
      << merge_log;
  EXPECT_TRUE(std::regex_search(merge_log, kCollectionTime)) << merge_log;
  EXPECT_FALSE(IsCollectionIndex(copy + "/collection.db"));
  EXPECT_EQ(HeadDigests(copy + "/collection.db"), expected);
}

TEST_F(SlurmClusterTest, CancelledShardResumesFromItsStore) {
  // The shard with the most maps (broken.png aside) stalls in the cut stage
  // of its first map; its other worker finishes the rest, then the task is
  // cancelled while it still runs.
  std::vector<std::vector<std::string>> names(kShards);
  for (const std::string& head : HeadDigests(reference())) {
    const std::string name = head.substr(0, head.find(' '));
    if (head.find(" match ") == std::string::npos) continue;
    for (int shard = 0; shard < kShards; ++shard) {
      if (InShard(name, Shard{shard, kShards})) names[shard].push_back(name);
    }
  }
  int target = 0;
  for (int shard = 0; shard < kShards; ++shard) {
    const bool has_broken = InShard("broken", Shard{shard, kShards});
    if (!has_broken && names[shard].size() > names[target].size()) target = shard;
  }
  ASSERT_FALSE(InShard("broken", Shard{target, kShards}));
  ASSERT_GE(names[target].size(), 3u);
  const std::string stalled = names[target].front();
  const int others = static_cast<int>(names[target].size()) - 1;

  const std::string stores = dir_->File("stores-cancel");
  const std::string shard_store = stores + "/shard-" + std::to_string(target) + ".db";
  const SubmittedCollection first = Submit(stores, "", {"AG_RUN_FAULT=stall:" + stalled + ":cut"});
  ASSERT_FALSE(first.collection.empty());
  const std::string task = first.shards + "_" + std::to_string(target);

  // Wait until the task runs and its store holds every map but the stalled one.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  int done = 0;
  while (std::chrono::steady_clock::now() < deadline) {
    try {
      if (fs::exists(shard_store)) {
        done = static_cast<int>(
            QueryColumn(shard_store, "SELECT map_id FROM heads WHERE stage = 'match'").size());
      }
    } catch (const std::exception&) {  // the file is being created: try again
    }
    if (done == others) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  ASSERT_EQ(done, others) << Logs(stores);
  ASSERT_EQ(cluster_->States(task).at(task), "RUNNING None");
  const CommandResult cancel = cluster_->Run({"scancel", task}, "/");
  ASSERT_EQ(cancel.exit_code, 0) << cancel.err;
  ASSERT_TRUE(cluster_->WaitUntilEnded({first.shards}, kJobTimeoutS)) << Logs(stores);
  EXPECT_EQ(cluster_->States(task).at(task).substr(0, 9), "CANCELLED");
  EXPECT_EQ(HeadDigests(shard_store).size(), static_cast<size_t>(others * kStagesPerMap + 4))
      << "import to prune of " << stalled << " should be stored";
  // The index job waits for every task to succeed, which can no longer happen.
  const std::string never = "PENDING DependencyNeverSatisfied";
  EXPECT_EQ(cluster_->WaitForState(first.collection, never, 30), never);
  EXPECT_FALSE(fs::exists(stores + "/collection.db"));
  ASSERT_EQ(cluster_->Run({"scancel", first.collection}, "/").exit_code, 0);

  // Queue that one shard again, with a new index job.
  const SubmittedCollection again = Submit(stores, std::to_string(target));
  ASSERT_FALSE(again.collection.empty());
  ASSERT_TRUE(cluster_->WaitUntilEnded({again.shards, again.collection}, kJobTimeoutS))
      << Logs(stores);
  EXPECT_EQ(cluster_->States(again.collection).at(again.collection), "COMPLETED None")
      << Logs(stores);
  const std::string index_log = CollectionLog(stores, again);
  EXPECT_TRUE(std::regex_search(index_log, kCollectionTime)) << index_log;
  EXPECT_EQ(RunTool("ag-store", {"verify", "--shallow", "--store", stores + "/collection.db"}).out,
            "checked " + std::to_string(36 * kStagesPerMap) + " artifacts: no problems\n");

  // It reused everything its store held: only cut, merge and match of the stalled map ran.
  const std::string log =
      ReadFile(stores + "/logs/shard-" + std::to_string(target) + "-job" + again.shards + ".out");
  std::smatch match;
  ASSERT_TRUE(std::regex_search(log, match, std::regex(R"(cache: (\d+) hits, (\d+) misses)")))
      << log;
  EXPECT_EQ(std::stoi(match[1]), others * kStagesPerMap + 4) << log;
  EXPECT_EQ(std::stoi(match[2]), 3) << log;
  EXPECT_NE(log.find("(" + std::to_string(others) + " fully cached)"), std::string::npos) << log;

  EXPECT_EQ(StoreHeadDigests(stores + "/collection.db"), HeadDigests(reference()));
  EXPECT_EQ(Failures(stores + "/collection.db"), Failures(reference()));

  // That shard queued once more (its task finds everything cached) and
  // indexed again: the index is replaced whole and still verifies.
  const SubmittedCollection third = Submit(stores, std::to_string(target));
  ASSERT_TRUE(cluster_->WaitUntilEnded({third.shards, third.collection}, kJobTimeoutS))
      << Logs(stores);
  EXPECT_EQ(cluster_->States(third.collection).at(third.collection), "COMPLETED None")
      << Logs(stores);
  EXPECT_EQ(StoreHeadDigests(stores + "/collection.db"), HeadDigests(reference()));
}

}  // namespace
}  // namespace areagraph::testing
