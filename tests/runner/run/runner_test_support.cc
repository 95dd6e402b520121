#include "tests/runner/run/runner_test_support.h"

#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "store/artifact_store.h"
#include "tests/support/raw_sqlite.h"
#include "tools/example_maps/random_floor_plan.h"

namespace areagraph::testing {

void WriteRandomMaps(const std::string& dir, int count, unsigned first_seed) {
  for (int i = 0; i < count; ++i) {
    const unsigned seed = first_seed + static_cast<unsigned>(i);
    floorplan::WritePlanPng(floorplan::RandomOfficePlan(seed),
                            dir + "/map_" + std::to_string(seed) + ".png");
  }
}

proto::RunSummary RunJson(const std::vector<std::string>& args, CommandResult* result) {
  std::vector<std::string> all = args;
  all.insert(all.begin(), "--json");
  CommandResult run = RunTool("ag-run", all);
  proto::RunSummary summary;
  const auto status = google::protobuf::util::JsonStringToMessage(run.out, &summary);
  EXPECT_TRUE(status.ok()) << "not a JSON summary:\n" << run.out << run.err;
  if (result != nullptr) *result = run;
  return summary;
}

StageCount CountOf(const proto::RunSummary& summary, const std::string& stage) {
  for (const auto& counts : summary.stages()) {
    if (counts.stage() == stage) return {counts.hits(), counts.misses()};
  }
  return {};
}

std::vector<std::pair<std::string, std::string>> GraphDigests(const std::string& store_path) {
  const auto store = OpenArtifactStore(store_path, StoreMode::kReadOnly);
  std::vector<std::pair<std::string, std::string>> digests;
  for (const MapRecord& map : store->ReadAllMaps()) {
    const auto head = store->ReadHead(map.name, "merge");
    digests.emplace_back(map.name, head ? head->payload_digest : "");
  }
  return digests;
}

std::vector<std::string> HeadDigestsOfFileAlone(const std::string& store_path) {
  TempDir elsewhere;
  const std::string copy = elsewhere.File("alone.db");
  std::filesystem::copy_file(store_path, copy);
  EXPECT_EQ(QueryColumn(copy, "PRAGMA quick_check"), std::vector<std::string>{"ok"});
  return HeadDigests(copy);
}

}  // namespace areagraph::testing
