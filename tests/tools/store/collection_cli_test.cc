// A collection of generated maps computed as three shard stores and indexed
// with ag-store index: every reading tool gives from the index what it gives
// from one unsharded run (or from the merge of the same shards, where run
// times show), also after the folder moved; a missing, damaged or changed
// shard is named; --only final and gc --keep final.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <regex>

#include "store/artifact_store.h"
#include "store/collection_index.h"
#include "tests/support/raw_sqlite.h"
#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

namespace fs = std::filesystem;

constexpr int kShards = 3;
constexpr int kMaps = 12;

CommandResult Ok(const CommandResult& result) {
  EXPECT_EQ(result.exit_code, 0) << result.out << result.err;
  return result;
}

void ExpectOneLineError(const CommandResult& result, const std::string& tool,
                        const std::string& needle) {
  EXPECT_EQ(result.exit_code, 1) << result.out << result.err;
  EXPECT_EQ(CountLines(result.err), 1) << result.err;
  EXPECT_EQ(result.err.rfind(tool + ": ", 0), 0u) << result.err;
  EXPECT_NE(result.err.find(needle), std::string::npos) << result.err;
}

class CollectionCliTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<TempDir>();
    Ok(RunTool("ag-make-collection", {"--count", std::to_string(kMaps), maps()}));
    WriteFile(maps() + "/broken.png", "not an image");
    EXPECT_EQ(
        RunTool("ag-run", {"--store", dir_->File("unsharded.db"), "--jobs", "2", maps()}).exit_code,
        1);
    fs::create_directories(dir_->File("shards"));
    for (int shard = 0; shard < kShards; ++shard) {
      RunTool("ag-run",
              {"--store", Shard(dir_->File("shards"), shard), "--shard",
               std::to_string(shard) + "/" + std::to_string(kShards), "--jobs", "2", maps()});
    }
    Ok(RunTool("ag-store", {"merge", dir_->File("merged.db"), Shard(dir_->File("shards"), 0),
                            Shard(dir_->File("shards"), 1), Shard(dir_->File("shards"), 2)}));
  }
  static void TearDownTestSuite() { dir_.reset(); }

  static std::string maps() { return dir_->File("maps"); }
  static std::string Shard(const std::string& folder, int shard) {
    return folder + "/shard-" + std::to_string(shard) + ".db";
  }
  static std::string unsharded() { return dir_->File("unsharded.db"); }
  static std::string merged() { return dir_->File("merged.db"); }

  // A copy of the three shard stores in `folder` (under this test's own
  // directory), indexed there as collection.db; returns the index.
  std::string IndexedCopy(const std::string& name, const std::vector<std::string>& more = {}) {
    const std::string folder = test_dir_.File(name);
    fs::copy(dir_->File("shards"), folder, fs::copy_options::recursive);
    std::vector<std::string> args = {"index", "--out", folder + "/collection.db"};
    args.insert(args.end(), more.begin(), more.end());
    for (int shard = 0; shard < kShards; ++shard) args.push_back(Shard(folder, shard));
    const CommandResult indexed = Ok(RunTool("ag-store", args));
    EXPECT_NE(indexed.out.find("indexed 3 shard stores (" + std::to_string(kMaps) + " maps, "),
              std::string::npos)
        << indexed.out;
    return folder + "/collection.db";
  }

  // The map names, from the unsharded run.
  static std::vector<std::string> MapNames() {
    return QueryColumn(unsharded(), "SELECT name FROM maps ORDER BY name");
  }

  // What `tool args --store STORE` writes to stdout, or to the file `out`
  // when the arguments name one ("OUT" is replaced by it).
  std::string Output(const std::string& tool, std::vector<std::string> args,
                     const std::string& store) {
    const std::string out = test_dir_.File("out-" + std::to_string(serial_++));
    bool to_file = false;
    for (std::string& arg : args) {
      if (arg == "OUT") {
        arg = out;
        to_file = true;
      }
    }
    args.insert(args.end(), {"--store", store});
    const CommandResult result = Ok(RunTool(tool, args));
    return to_file ? ReadFile(out) : result.out;
  }

  static std::unique_ptr<TempDir> dir_;
  TempDir test_dir_;
  int serial_ = 0;
};

std::unique_ptr<TempDir> CollectionCliTest::dir_;

TEST_F(CollectionCliTest, EveryReadingToolReadsTheIndexAsOneStore) {
  const std::string index = IndexedCopy("collection");
  ASSERT_EQ(MapNames().size(), static_cast<size_t>(kMaps));
  // Exports and pictures are those of one unsharded run, byte for byte.
  for (const std::string& map : MapNames()) {
    EXPECT_EQ(
        Output("ag-export", {"--map", map, "--format", "geojson", "--out", "OUT"}, index),
        Output("ag-export", {"--map", map, "--format", "geojson", "--out", "OUT"}, unsharded()))
        << map;
  }
  const std::string map = MapNames().front();
  for (const std::string& format : {"json", "osmag", "protojson", "labels", "preview"}) {
    EXPECT_EQ(Output("ag-export", {"--map", map, "--format", format, "--out", "OUT"}, index),
              Output("ag-export", {"--map", map, "--format", format, "--out", "OUT"}, unsharded()))
        << format;
  }
  for (const std::string& stage : {"clean", "prune", "match"}) {
    EXPECT_EQ(Output("ag-render", {"--map", map, "--stage", stage, "--out", "OUT"}, index),
              Output("ag-render", {"--map", map, "--stage", stage, "--out", "OUT"}, unsharded()))
        << stage;
  }
  EXPECT_EQ(Output("ag-inspect", {"--map", map, "--stage", "cut", "--json"}, index),
            Output("ag-inspect", {"--map", map, "--stage", "cut", "--json"}, unsharded()));
  // Listings with run times and keys are those of the same shards merged.
  for (const std::vector<std::string>& args :
       std::vector<std::vector<std::string>>{{},
                                             {"--map", map},
                                             {"--map", map, "--stage", "merge"},
                                             {"--history", map},
                                             {"--failures"}}) {
    EXPECT_EQ(Output("ag-inspect", args, index), Output("ag-inspect", args, merged()))
        << (args.empty() ? "(maps)" : args[0]);
  }
  EXPECT_EQ(Output("ag-export", {"--map", map, "--format", "html", "--out", "OUT"}, index),
            Output("ag-export", {"--map", map, "--format", "html", "--out", "OUT"}, merged()));
  EXPECT_EQ(Output("ag-store", {"failures"}, index), Output("ag-store", {"failures"}, merged()));

  // ag-run --report without MAP: the report of the store's maps, nothing run.
  const std::string from_index = test_dir_.File("report-index");
  const std::string from_merged = test_dir_.File("report-merged");
  Ok(RunTool("ag-run", {"--store", index, "--report", from_index}));
  Ok(RunTool("ag-run", {"--store", merged(), "--report", from_merged}));
  EXPECT_EQ(ReadFile(from_index + "/index.html"), ReadFile(from_merged + "/index.html"));
  int pages = 0;
  for (const auto& page : fs::directory_iterator(from_merged + "/maps")) {
    EXPECT_EQ(ReadFile(from_index + "/maps/" + page.path().filename().string()),
              ReadFile(page.path()))
        << page.path();
    ++pages;
  }
  EXPECT_EQ(pages, kMaps);

  EXPECT_EQ(Output("ag-store", {"verify"}, index),
            "checked " + std::to_string(7 * kMaps) + " artifacts: no problems\n");
  EXPECT_EQ(Output("ag-store", {"verify", "--shallow"}, index),
            "checked " + std::to_string(7 * kMaps) + " artifacts: no problems\n");
  // One file again: the merge of an index is the merge of its shards.
  Ok(RunTool("ag-store", {"merge", test_dir_.File("one.db"), index}));
  EXPECT_EQ(HeadDigests(test_dir_.File("one.db")), HeadDigests(merged()));
}

// ag-eval reads label images, not stores: it scores the labels exported from
// the index exactly as the unsharded run's (every pixel and segment agrees).
TEST_F(CollectionCliTest, EvalScoresTheIndexsLabelsAsTheUnshardedRuns) {
  const std::string index = IndexedCopy("collection");
  for (const std::string& map : {MapNames().front(), MapNames().back()}) {
    const std::string result = test_dir_.File("index-" + std::to_string(serial_) + ".png");
    const std::string truth = test_dir_.File("unsharded-" + std::to_string(serial_++) + ".png");
    Ok(RunTool("ag-export",
               {"--store", index, "--map", map, "--format", "labels", "--out", result}));
    Ok(RunTool("ag-export",
               {"--store", unsharded(), "--map", map, "--format", "labels", "--out", truth}));
    const std::string scores =
        Ok(RunTool("ag-eval", {"--result", result, "--gt", truth, "--gt-style", "labels"})).out;
    EXPECT_EQ(scores.rfind("MCC 1.000\nprecision 1.000\nrecall 1.000\n", 0), 0u) << scores;
  }
}

TEST_F(CollectionCliTest, WritersRefuseAnIndex) {
  const std::string index = IndexedCopy("collection");
  const std::string refused = "is a collection index of 3 shard stores, which is only read";
  ExpectOneLineError(RunTool("ag-run", {"--store", index, maps()}), "ag-run", refused);
  ExpectOneLineError(RunTool("ag-clean", {"--store", index, "--map", MapNames().front()}),
                     "ag-clean", refused);
  ExpectOneLineError(RunTool("ag-store", {"backup", "--store", index, test_dir_.File("b.db")}),
                     "ag-store", "is a collection index: copy its folder");
  ExpectOneLineError(RunTool("ag-store", {"merge", index, unsharded()}), "ag-store", refused);
  // Indexing over a store that is not an index is refused too.
  ExpectOneLineError(
      RunTool("ag-store", {"index", "--out", merged(), Shard(fs::path(index).parent_path(), 0)}),
      "ag-store", "exists and is not a collection index");
  EXPECT_EQ(HeadDigests(index.substr(0, index.rfind('/')) + "/shard-0.db"),
            HeadDigests(Shard(dir_->File("shards"), 0)));
}

TEST_F(CollectionCliTest, MovedFolderStillReads) {
  const std::string index = IndexedCopy("collection");
  const std::string moved = test_dir_.File("somewhere/else");
  fs::create_directories(fs::path(moved).parent_path());
  fs::rename(fs::path(index).parent_path(), moved);
  const std::string map = MapNames().back();
  EXPECT_EQ(
      Output("ag-export", {"--map", map, "--format", "geojson", "--out", "OUT"},
             moved + "/collection.db"),
      Output("ag-export", {"--map", map, "--format", "geojson", "--out", "OUT"}, unsharded()));
  Ok(RunTool("ag-store", {"verify", "--store", moved + "/collection.db"}));
}

TEST_F(CollectionCliTest, MissingShardIsNamedWithTheMap) {
  const std::string index = IndexedCopy("collection");
  const std::string folder = fs::path(index).parent_path();
  fs::remove(Shard(folder, 1));
  const std::vector<std::string> in_shard =
      QueryColumn(index,
                  "SELECT m.name FROM maps m JOIN shards s ON s.id = m.shard_id"
                  " WHERE s.path = 'shard-1.db' ORDER BY m.name");
  ASSERT_FALSE(in_shard.empty());
  ExpectOneLineError(RunTool("ag-export", {"--store", index, "--map", in_shard.front(), "--format",
                                           "geojson", "--out", test_dir_.File("x.geojson")}),
                     "ag-export",
                     "map '" + in_shard.front() +
                         "' is in shard store 'shard-1.db' of collection index '" + index +
                         "', which is missing (no file '" + folder + "/shard-1.db')");
  EXPECT_FALSE(fs::exists(test_dir_.File("x.geojson")));
  // What the index itself holds still lists; the other shards still read.
  EXPECT_NE(Output("ag-inspect", {}, index).find(in_shard.front()), std::string::npos);
  const std::string other = QueryColumn(index,
                                        "SELECT m.name FROM maps m JOIN shards s"
                                        " ON s.id = m.shard_id WHERE s.path = 'shard-0.db'")
                                .front();
  Ok(RunTool("ag-export", {"--store", index, "--map", other, "--format", "json", "--out", "-"}));
  for (const std::vector<std::string>& shallow :
       std::vector<std::vector<std::string>>{{}, {"--shallow"}}) {
    std::vector<std::string> args = {"verify", "--store", index};
    args.insert(args.end(), shallow.begin(), shallow.end());
    const CommandResult verified = RunTool("ag-store", args);
    EXPECT_EQ(verified.exit_code, 1) << verified.out << verified.err;
    EXPECT_NE(verified.out.find(in_shard.front() +
                                " - -: shard store 'shard-1.db' is missing (no "
                                "file '" +
                                folder + "/shard-1.db'): the index's " +
                                std::to_string(in_shard.size()) + " maps in it"),
              std::string::npos)
        << verified.out;
    EXPECT_NE(verified.out.find(": 1 problem\n"), std::string::npos) << verified.out;
  }
}

TEST_F(CollectionCliTest, DamagedShardIsNamed) {
  const std::string index = IndexedCopy("collection");
  const std::string folder = fs::path(index).parent_path();
  const std::string map =
      QueryColumn(Shard(folder, 2), "SELECT name FROM maps ORDER BY name").front();
  const std::string key = QueryColumn(Shard(folder, 2),
                                      "SELECT a.cache_key FROM artifacts a JOIN maps m"
                                      " ON m.id = a.map_id WHERE m.name = '" +
                                          map + "' AND a.stage = 'match'")
                              .front();
  FlipPayloadByte(Shard(folder, 2), key, 5);
  ExpectOneLineError(
      RunTool("ag-export", {"--store", index, "--map", map, "--format", "json", "--out", "-"}),
      "ag-export", "of map '" + map + "' in store '" + Shard(folder, 2) + "' is corrupt");
  const CommandResult verified = RunTool("ag-store", {"verify", "--store", index});
  EXPECT_EQ(verified.exit_code, 1) << verified.out;
  EXPECT_NE(
      verified.out.find(map + " match " + key.substr(0, 12) + ": in shard store 'shard-2.db': "),
      std::string::npos)
      << verified.out;
  // --shallow reads no payload: the rows still agree with the index.
  Ok(RunTool("ag-store", {"verify", "--store", index, "--shallow"}));
}

TEST_F(CollectionCliTest, ShardRunAgainIsReportedUntilIndexedAgain) {
  const std::string index = IndexedCopy("collection");
  const std::string folder = fs::path(index).parent_path();
  // Shard 0 runs again with another room width: its cut, merge and match
  // heads move, as after a requeued task that computed more.
  RunTool("ag-run",
          {"--store", Shard(folder, 0), "--shard", "0/3", "--set", "cut.room_width_m=1.3", maps()});
  const std::string map = QueryColumn(Shard(folder, 0), "SELECT name FROM maps ORDER BY name")[0];
  const CommandResult stale = RunTool("ag-store", {"verify", "--store", index, "--shallow"});
  EXPECT_EQ(stale.exit_code, 1);
  EXPECT_NE(stale.out.find(map + " cut "), std::string::npos) << stale.out;
  EXPECT_NE(stale.out.find("head in shard store 'shard-0.db': "), std::string::npos) << stale.out;
  EXPECT_NE(stale.out.find("the shard changed after the index was written; run ag-store index "
                           "again"),
            std::string::npos)
      << stale.out;

  const CommandResult again = Ok(RunTool(
      "ag-store", {"index", "--out", index, Shard(folder, 0), Shard(folder, 1), Shard(folder, 2)}));
  EXPECT_EQ(
      Output("ag-store", {"verify", "--shallow"}, index).find("no problems") != std::string::npos,
      true);
  EXPECT_EQ(
      Output("ag-export", {"--map", map, "--format", "geojson", "--out", "OUT"}, index),
      Output("ag-export", {"--map", map, "--format", "geojson", "--out", "OUT"}, Shard(folder, 0)));
  EXPECT_FALSE(fs::exists(folder + "/.collection.db." + std::to_string(0) + ".tmp"));
  int files = 0;
  for ([[maybe_unused]] const auto& file : fs::directory_iterator(folder)) ++files;
  EXPECT_LE(files, 1 + 3 * kShards) << "no temporary left beside the index";
}

TEST_F(CollectionCliTest, FinalOnlyIndexAndShardsTrimmedToIt) {
  const std::string index = IndexedCopy("collection", {"--only", "final"});
  const std::string folder = fs::path(index).parent_path();
  const std::string map = MapNames()[1];
  EXPECT_EQ(
      Output("ag-export", {"--map", map, "--format", "geojson", "--out", "OUT"}, index),
      Output("ag-export", {"--map", map, "--format", "geojson", "--out", "OUT"}, unsharded()));
  EXPECT_EQ(Output("ag-inspect", {"--map", map}, index).find("import "), std::string::npos);
  ExpectOneLineError(RunTool("ag-render", {"--store", index, "--map", map, "--stage", "clean",
                                           "--out", test_dir_.File("x.png")}),
                     "ag-render", "has no import artifact");

  const int64_t before = static_cast<int64_t>(fs::file_size(Shard(folder, 0)));
  const CommandResult trimmed =
      Ok(RunTool("ag-store", {"gc", "--store", index, "--keep", "final", "--vacuum"}));
  EXPECT_NE(trimmed.out.find("shard-0.db: removed "), std::string::npos) << trimmed.out;
  EXPECT_NE(trimmed.out.find(": the heads of merge and match) into " + index), std::string::npos)
      << trimmed.out;
  EXPECT_LT(static_cast<int64_t>(fs::file_size(Shard(folder, 0))), before / 4) << trimmed.out;
  EXPECT_EQ(QueryColumn(Shard(folder, 0), "SELECT DISTINCT stage FROM artifacts ORDER BY 1"),
            (std::vector<std::string>{"match", "merge"}));
  EXPECT_EQ(Output("ag-store", {"verify"}, index).find("no problems") != std::string::npos, true);
  EXPECT_EQ(
      Output("ag-export", {"--map", map, "--format", "geojson", "--out", "OUT"}, index),
      Output("ag-export", {"--map", map, "--format", "geojson", "--out", "OUT"}, unsharded()));

  // The cache then holds the final stages only: a run of the shard computes
  // import to cut again and finds merge and match.
  const CommandResult rerun =
      RunTool("ag-run", {"--store", Shard(folder, 0), "--shard", "0/3", "--jobs", "1", maps()});
  const int maps_in_shard =
      static_cast<int>(QueryColumn(Shard(folder, 0), "SELECT name FROM maps").size());
  std::smatch counts;
  ASSERT_TRUE(
      std::regex_search(rerun.out, counts, std::regex(R"(cache: (\d+) hits, (\d+) misses)")))
      << rerun.out;
  EXPECT_EQ(std::stoi(counts[1]), 2 * maps_in_shard) << rerun.out;
  EXPECT_EQ(std::stoi(counts[2]), 5 * maps_in_shard) << rerun.out;
}

// Telling an index from a store must not disturb a store that this process
// is writing: POSIX drops every lock a process holds on a file when any of its
// descriptors of that file closes, and another process could then remove the
// writer's log under it (its later commits would be lost to every reader).
TEST(CollectionIndexPeekTest, KeepsTheLocksOfTheProcesssOtherConnections) {
  TempDir dir;
  const std::string path = dir.File("s.db");
  const std::unique_ptr<ArtifactStore> writer = OpenArtifactStore(path);
  writer->LeaveWriteAheadLogOnClose();
  writer->WriteArtifact(MakeArtifact("hall", "import", "key-a", "first"));
  EXPECT_FALSE(IsCollectionIndex(path));
  OpenArtifactStore(path, StoreMode::kReadOnly);  // the same check inside
  // Another process writes and closes: as the last connection it would
  // remove the log if this process's locks were gone.
  Ok(RunTool("ag-store", {"gc", "--store", path}));
  writer->WriteArtifact(MakeArtifact("hall", "clean", "key-b", "second"));
  EXPECT_TRUE(std::filesystem::exists(path + "-wal"));
  const CommandResult listed = Ok(RunTool("ag-inspect", {"--store", path, "--map", "hall"}));
  EXPECT_NE(listed.out.find("key-b"), std::string::npos) << listed.out;
}

TEST_F(CollectionCliTest, HelpSaysWhatTheCacheLoses) {
  const CommandResult index_help = Ok(RunTool("ag-store", {"index", "--help"}));
  EXPECT_NE(index_help.out.find("--only"), std::string::npos);
  EXPECT_NE(index_help.out.find("relative"), std::string::npos);
  const CommandResult gc_help = Ok(RunTool("ag-store", {"gc", "--help"}));
  EXPECT_NE(gc_help.out.find("computes import to cut again"), std::string::npos) << gc_help.out;
  EXPECT_EQ(RunTool("ag-store", {"index", "--out", test_dir_.File("c.db"), "--only", "some",
                                 Shard(dir_->File("shards"), 0)})
                .exit_code,
            2);
}

}  // namespace
}  // namespace areagraph::testing
