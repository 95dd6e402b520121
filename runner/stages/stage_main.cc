#include "runner/stages/stage_main.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <optional>

#include "common/process_setup/freed_memory.h"
#include "common/process_setup/huge_page_restart.h"
#include "common/text.h"
#include "stages/common/command_line.h"
#include "stages/pipeline/stage.h"

namespace areagraph {

void RestartForBigMap(std::unique_ptr<ArtifactStore>& store,
                      const std::function<std::unique_ptr<ArtifactStore>()>& open,
                      const std::string& map_name) {
  if (!MayRestartWithHugePageTunable()) return;
  const std::optional<MapRecord> map = store->ReadMap(map_name);
  if (!map || !IsBigMapImage(map->source_path)) return;
  store.reset();
  RestartWithHugePageTunable();
  store = open();
}

int RunStageMain(const StageInfo& info, int argc, char** argv) {
  const StageDefinition& stage = StageOf(info);
  const std::string tool = std::string("ag-") + info.name;
  CLI::App app{stage.description};
  StageCommandLine flags;
  AddStageFlags(app, flags);
  return RunCommand(tool, app, argc, argv, [&] {
    const proto::PipelineOptions options = LoadPipelineOptions(flags);
    const auto open = [&] { return OpenArtifactStore(flags.store_path); };
    std::unique_ptr<ArtifactStore> store = open();
    RestartForBigMap(store, open, flags.map_name);
    const StageRun run = RunStageOnHeads(*store, flags.map_name, stage, options, flags.force,
                                         /*memo=*/nullptr, ReturnFreedMemory);
    std::printf("%s: map '%s': %s, %.0f ms, key %s (%s)\n", tool.c_str(), flags.map_name.c_str(),
                run.summary.c_str(), run.elapsed_ms, ShortKey(run.cache_key).c_str(),
                run.cache_hit ? "cached" : "computed");
    std::fputs(HugePageRestartLine(tool).c_str(), stdout);
    return 0;
  });
}

}  // namespace areagraph
