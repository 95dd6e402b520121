// ag-pipeline: every stage after ag-import, for one imported map.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>

#include "common/process_setup/freed_memory.h"
#include "common/process_setup/huge_page_restart.h"
#include "common/text.h"
#include "runner/stages/stage_main.h"
#include "stages/common/command_line.h"
#include "stages/pipeline/map_pipeline.h"
#include "store/write_behind_store.h"

using namespace areagraph;

int main(int argc, char** argv) {
  CLI::App app{"Runs every stage after ag-import (" + StageNameList() +
               ") in one go for a map that ag-import has stored, reusing every cached result; "
               "prints one line per stage."};
  StageCommandLine flags;
  AddStageFlags(app, flags);
  return RunCommand("ag-pipeline", app, argc, argv, [&] {
    const proto::PipelineOptions options = LoadPipelineOptions(flags);
    const auto open = [&] { return OpenWriteBehindStore(flags.store_path); };
    std::unique_ptr<ArtifactStore> store = open();
    RestartForBigMap(store, open, flags.map_name);
    std::string last_summary;
    PipelineObserver observer;
    observer.on_done = [&](const StageInfo& stage, const StageRun& run) {
      last_summary = run.summary;
      std::printf("ag-pipeline: map '%s': %-7s %-8s %6.0f ms  key %s  %s\n", flags.map_name.c_str(),
                  stage.name, run.cache_hit ? "cached" : "computed", run.elapsed_ms,
                  ShortKey(run.cache_key).c_str(), run.summary.c_str());
      std::fflush(stdout);
    };
    observer.between_steps = ReturnFreedMemory;
    const std::vector<StageInfo> stages = PipelineStages();
    RunMapPipeline(*store, flags.map_name, options, flags.force, observer, stages.front(),
                   stages.back());
    ReturnFreedMemory();  // as RunOneMap does after a map
    std::printf("ag-pipeline: map '%s': %s\n", flags.map_name.c_str(), last_summary.c_str());
    std::fputs(HugePageRestartLine("ag-pipeline").c_str(), stdout);
    return 0;
  });
}
