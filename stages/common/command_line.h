#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

#include "proto/pipeline_options.pb.h"

namespace areagraph {

// The flags that every stage executable shares.
struct StageCommandLine {
  std::string store_path = "areagraph.db";
  std::string map_name;
  std::string options_file;
  std::vector<std::string> overrides;
  bool force = false;
};

// Adds --store, --map, --options, --set and --force to `app`. `map_required`
// is false for ag-import, whose map name defaults to the file's stem.
void AddStageFlags(CLI::App& app, StageCommandLine& flags, bool map_required = true);

// The options file (if any) with every --set applied in order, checked
// (CheckPipelineOptions): bad options fail before any tool opens a store.
proto::PipelineOptions LoadPipelineOptions(const StageCommandLine& flags);

// Parses the command line and runs `body`, turning every error into one line
// "<tool>: <message>" on stderr and a non-zero exit: 2 for bad usage (a bad
// flag, or an OptionsError: a bad option key, value or combination), 1 for
// everything else. --help prints the help and --version the version
// (VersionText), each exiting 0. Standard output is flushed and checked after
// `body`, so a lost report is an error too. The command line is what a
// restart for a big map runs again (SetRestartCommandLine).
int RunCommand(const std::string& tool, CLI::App& app, int argc, char** argv,
               const std::function<int()>& body);

}  // namespace areagraph
