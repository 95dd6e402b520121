#include "stages/common/command_line.h"

#include <iostream>
#include <new>
#include <optional>

#include "common/error.h"
#include "common/process_setup/huge_page_restart.h"
#include "common/text.h"
#include "common/version.h"
#include "stages/common/output_file.h"
#include "stages/common/pipeline_options.h"
#include "stages/common/pipeline_options_check.h"
#include "store/artifact_store.h"

namespace areagraph {

void AddStageFlags(CLI::App& app, StageCommandLine& flags, bool map_required) {
  app.add_option("--store", flags.store_path, "SQLite artifact store")->capture_default_str();
  CLI::Option* map = app.add_option("--map", flags.map_name, "name of the map in the store");
  if (map_required) map->required();
  app.add_option("--options", flags.options_file,
                 "PipelineOptions in protobuf text format (see examples/options/)");
  app.add_option("--set", flags.overrides,
                 "override one option, e.g. --set cut.room_width_m=1.1 (repeatable)")
      ->take_last()
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  app.add_flag("--force", flags.force, "recompute even when the result is cached");
}

proto::PipelineOptions LoadPipelineOptions(const StageCommandLine& flags) {
  proto::PipelineOptions options;
  if (!flags.options_file.empty()) options = ReadOptionsFile(flags.options_file);
  for (const std::string& assignment : flags.overrides) ApplyOverride(assignment, &options);
  CheckPipelineOptions(options);
  return options;
}

namespace {

// Exit 0 once what --help or --version printed reached standard output, else 1.
int FlushedExit(const std::string& tool) {
  try {
    FlushStandardOutput();
    return 0;
  } catch (const std::exception& e) {
    std::cerr << tool << ": " << e.what() << "\n";
    return 1;
  }
}

}  // namespace

int RunCommand(const std::string& tool, CLI::App& app, int argc, char** argv,
               const std::function<int()>& body) {
  app.set_version_flag("--version", std::string(VersionText()));
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return FlushedExit(tool);
  } catch (const CLI::CallForVersion& version) {
    std::cout << tool << ": " << version.what() << "\n";
    return FlushedExit(tool);
  } catch (const CLI::ParseError& e) {
    std::cerr << tool << ": " << OneLine(e.what()) << " (see --help)\n";
    return 2;
  }
  SetRestartCommandLine(argv);
  try {
    const int exit_code = body();
    FlushStandardOutput();  // a report lost on a full disk is a failure
    // A store closed by `body` whose log stayed beside it (a full disk):
    // the file alone is not the store, which the user must know.
    if (const std::optional<std::string> problem = TakeUnfoldedLogProblem()) {
      std::cerr << tool << ": " << *problem << "\n";
      return exit_code == 0 ? 1 : exit_code;
    }
    return exit_code;
  } catch (const OptionsError& e) {
    // A bad option key, value or combination is bad usage, like a bad flag.
    std::cerr << tool << ": " << OneLine(e.what()) << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << tool << ": out of memory\n";
  } catch (const std::exception& e) {
    std::cerr << tool << ": " << OneLine(e.what()) << "\n";  // a library's may span lines
  }
  return 1;
}

}  // namespace areagraph
