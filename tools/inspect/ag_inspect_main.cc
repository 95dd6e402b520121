// ag-inspect: lists the maps and artifacts of a store and dumps artifacts.
#include <CLI/CLI.hpp>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "common/error.h"
#include "stages/common/command_line.h"
#include "stages/common/output_file.h"
#include "store/artifact_store.h"
#include "tools/inspect/failure_report.h"
#include "tools/inspect/history_report.h"
#include "tools/inspect/store_report.h"

// CLI::Range lets NaN through (every comparison with it is false).
const CLI::Validator Finite(
    [](std::string& text) {
      double value = 0;
      return CLI::detail::lexical_cast(text, value) && std::isfinite(value)
                 ? std::string()
                 : "must be a finite number, got " + text;
    },
    "FINITE");

int main(int argc, char** argv) {
  CLI::App app{
      "Lists the maps in an areagraph store, the artifacts of one map, or dumps one artifact.\n"
      "  ag-inspect --store S                       maps\n"
      "  ag-inspect --store S --map M               artifacts of M (* = head)\n"
      "  ag-inspect --store S --map M --stage ST    summary of the head artifact of ST\n"
      "  ag-inspect --store S --map M --key K --json   artifact with key prefix K as JSON\n"
      "  ag-inspect --store S --failures [--json]   maps that failed in a runner, and why\n"
      "  ag-inspect --store S --history M           the versions of M's Area Graph\n"
      "  ag-inspect --store S --map M --diff A B [--json]   what changed from version A to B\n"
      "      (a version number, a key prefix or 'head'; see --history)"};
  std::string store_path = "areagraph.db", map_name, stage, key_prefix;
  bool json = false, failures = false;
  std::string history_map;
  std::vector<std::string> diff_versions;
  areagraph::DiffThresholds thresholds;
  app.add_option("--store", store_path, "SQLite artifact store")->capture_default_str();
  app.add_option("--map", map_name, "map to list or dump");
  app.add_option("--stage", stage, "stage whose head artifact to show (import, clean, ...)");
  app.add_option("--key", key_prefix, "artifact key or a unique prefix of it");
  app.add_flag("--json", json, "dump the artifact (or the failures) as JSON instead of a summary");
  app.add_flag("--failures", failures, "list the failed maps: map, stage, time, message");
  app.add_option("--history", history_map,
                 "list the versions of this map's Area Graph: number, key, time, predecessor");
  app.add_option("--diff", diff_versions,
                 "compare two versions of --map's Area Graph: areas and passages added, removed, "
                 "changed (split, merged, grown, shrunk) and unchanged, by stable id")
      ->expected(2);
  app.add_option("--size-threshold", thresholds.size,
                 "--diff: an area grew or shrank (a passage's width changed) when it changed by "
                 "more than this fraction")
      ->capture_default_str()
      ->check(Finite & CLI::Range(0.0, 100.0));
  app.add_option("--move-threshold", thresholds.passage_m,
                 "--diff: a passage changed when it moved more than this many metres")
      ->capture_default_str()
      ->check(Finite & CLI::Range(0.0, 1e6));
  return areagraph::RunCommand("ag-inspect", app, argc, argv, [&] {
    auto store = areagraph::OpenArtifactStore(store_path, areagraph::StoreMode::kReadOnly);
    if (!history_map.empty()) {
      if (failures || !map_name.empty() || !stage.empty() || !key_prefix.empty() || json ||
          !diff_versions.empty()) {
        throw areagraph::InputError("--history lists one map's versions; drop the other flags");
      }
      areagraph::PrintHistory(*store, history_map, std::cout);
    } else if (!diff_versions.empty()) {
      if (map_name.empty()) throw areagraph::InputError("--diff needs --map");
      if (failures || !stage.empty() || !key_prefix.empty()) {
        throw areagraph::InputError(
            "--diff compares two versions; drop --failures, --stage, --key");
      }
      areagraph::PrintVersionDiff(*store, map_name, diff_versions[0], diff_versions[1], thresholds,
                                  json, std::cout);
    } else if (failures) {
      if (!map_name.empty() || !stage.empty() || !key_prefix.empty()) {
        throw areagraph::InputError("--failures lists every map; drop --map, --stage and --key");
      }
      if (json) {
        std::ostringstream text;
        areagraph::PrintFailuresJson(store->ReadFailures(), text);
        areagraph::WriteOutputFile(areagraph::kStandardOutputName, text.str());
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
      if (json) {  // through the checked writer: a dump can be many megabytes
        std::ostringstream text;
        areagraph::PrintArtifactJson(artifact, text);
        areagraph::WriteOutputFile(areagraph::kStandardOutputName, text.str());
      } else {
        areagraph::PrintArtifactSummary(artifact, std::cout);
      }
    }
    return 0;
  });
}
