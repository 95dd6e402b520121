#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "runner/run/map_worker.h"
#include "stages/common/command_line.h"

namespace areagraph {

// ag-run's command line.
struct RunFlags {
  StageCommandLine stage;  // --store, --options, --set, --force
  std::vector<std::string> maps;
  std::string from_stage;
  std::string only_stage;
  int jobs = 0;
  int threads_per_map = 0;  // 0: ThreadsPerMap's share of the cores
  std::string shard;
  bool publish = false;
  std::string url;
  bool json = false;
  bool print_options = false;
};

// Adds ag-run's flags and MAP arguments to `app`; --jobs defaults to the
// number of cores, --threads-per-map to 0 (each worker's share of them).
void AddRunFlags(CLI::App& app, RunFlags& flags);

// Checks what needs no map: MAP given unless --print-options, --jobs, --threads-per-map, stage
// names, --url without --publish. Throws OptionsError.
void CheckRunFlags(const CLI::App& app, const RunFlags& flags);

// The run settings that --store, --from, --only and --force ask for.
RunSettings SettingsFrom(const RunFlags& flags);

}  // namespace areagraph
