#include "tests/stages/import/import_test_util.h"

#include <stdexcept>

#include "stages/pipeline/stage.h"
#include "tests/support/test_support.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {

void WriteTwoRoomPng(const std::string& path, bool door_open) {
  using namespace floorplan;
  FloorPlan plan(12, 7);
  DrawRoom(plan, {1, 1, 5, 5});
  DrawRoom(plan, {6, 1, 5, 5});
  if (door_open) DrawDoor(plan, 6, 3.5, 0.9, WallDirection::kVertical);
  WritePlanPng(plan, path);
}

proto::GridMap ReadHeadGridMap(const std::string& store_path, const std::string& map_name,
                               std::string* cache_key) {
  const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(store_path, StoreMode::kReadOnly);
  return ReadHeadArtifact<proto::GridMap>(*store, map_name, kImportStage, cache_key);
}

size_t ArtifactCount(const std::string& store_path, const std::string& map_name) {
  const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(store_path, StoreMode::kReadOnly);
  return store->ReadArtifactSummaries(map_name).size();
}

std::string DumpStore(const std::string& store_path) {
  const CommandResult dump = RunProgram({"sqlite3", store_path, ".dump"});
  if (dump.exit_code != 0) throw std::runtime_error("sqlite3 .dump failed: " + dump.err);
  return dump.out;
}

}  // namespace areagraph::testing
