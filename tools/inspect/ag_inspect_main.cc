// ag-inspect: lists the maps and artifacts of a store and dumps artifacts.
#include <CLI/CLI.hpp>
#include <iostream>

#include "common/error.h"
#include "stages/common/command_line.h"
#include "store/artifact_store.h"
#include "tools/inspect/failure_report.h"
#include "tools/inspect/store_report.h"

int main(int argc, char** argv) {
  CLI::App app{
      "Lists the maps in an areagraph store, the artifacts of one map, or dumps one artifact.\n"
      "  ag-inspect --store S                       maps\n"
      "  ag-inspect --store S --map M               artifacts of M (* = head)\n"
      "  ag-inspect --store S --map M --stage ST    summary of the head artifact of ST\n"
      "  ag-inspect --store S --map M --key K --json   artifact with key prefix K as JSON\n"
      "  ag-inspect --store S --failures [--json]   maps that failed in a runner, and why"};
  std::string store_path = "areagraph.db", map_name, stage, key_prefix;
  bool json = false, failures = false;
  app.add_option("--store", store_path, "SQLite artifact store")->capture_default_str();
  app.add_option("--map", map_name, "map to list or dump");
  app.add_option("--stage", stage, "stage whose head artifact to show (import, clean, ...)");
  app.add_option("--key", key_prefix, "artifact key or a unique prefix of it");
  app.add_flag("--json", json, "dump the artifact (or the failures) as JSON instead of a summary");
  app.add_flag("--failures", failures, "list the failed maps: map, stage, time, message");
  return areagraph::RunCommand("ag-inspect", app, argc, argv, [&] {
    auto store = areagraph::OpenArtifactStore(store_path, areagraph::StoreMode::kReadOnly);
    if (failures) {
      if (!map_name.empty() || !stage.empty() || !key_prefix.empty()) {
        throw areagraph::InputError("--failures lists every map; drop --map, --stage and --key");
      }
      if (json) {
        areagraph::PrintFailuresJson(store->ReadFailures(), std::cout);
      } else {
        areagraph::PrintFailureList(store->ReadFailures(), std::cout);
      }
    } else if (map_name.empty()) {
      if (!stage.empty() || !key_prefix.empty() || json) {
        throw areagraph::InputError("--stage, --key and --json need --map");
      }
      areagraph::PrintMapList(*store, std::cout);
    } else if (stage.empty() && key_prefix.empty()) {
      if (json) throw areagraph::InputError("--json needs --stage or --key");
      areagraph::PrintArtifactList(*store, map_name, std::cout);
    } else {
      const areagraph::ArtifactRecord artifact =
          areagraph::FindArtifact(*store, map_name, stage, key_prefix);
      if (json) {
        areagraph::PrintArtifactJson(artifact, std::cout);
      } else {
        areagraph::PrintArtifactSummary(artifact, std::cout);
      }
    }
    return 0;
  });
}
