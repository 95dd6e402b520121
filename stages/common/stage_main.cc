#include "stages/common/stage_main.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>

#include "common/text.h"
#include "stages/common/command_line.h"
#include "stages/common/stage.h"

namespace areagraph {

int RunStageMain(const StageInfo& info, int argc, char** argv) {
  const StageDefinition& stage = StageOf(info);
  const std::string tool = std::string("ag-") + info.name;
  CLI::App app{stage.description};
  StageCommandLine flags;
  AddStageFlags(app, flags);
  return RunCommand(tool, app, argc, argv, [&] {
    const proto::PipelineOptions options = LoadPipelineOptions(flags);
    const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(flags.store_path);
    const StageRun run = RunStageOnHeads(*store, flags.map_name, stage, options, flags.force);
    std::printf("%s: map '%s': %s, %.0f ms, key %s (%s)\n", tool.c_str(), flags.map_name.c_str(),
                run.summary.c_str(), run.elapsed_ms, ShortKey(run.cache_key).c_str(),
                run.cache_hit ? "cached" : "computed");
    return 0;
  });
}

}  // namespace areagraph
