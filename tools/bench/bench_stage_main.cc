// ag-bench-stage: the CPU time of one stage's compute on a stored map, to set
// a tool's whole-process CPU time against (tools/bench-speed.sh's render
// table: ag-render of a stage against that stage's compute).
//
// Reads the head artifacts of the stage's inputs once (not timed), then runs
// the stage's compute function --repeat times and prints the median CPU
// milliseconds (user + system of the whole process, so OpenCV's and TBB's
// worker threads count) and the median wall milliseconds. The import, which
// reads a file, is timed as ag-import does it: reading the map's source file
// and decoding it. A benchmark: it checks nothing.
#include <time.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "common/error.h"
#include "common/process_setup/freed_memory.h"
#include "stages/common/command_line.h"
#include "stages/import/import_stage.h"
#include "stages/pipeline/stage.h"
#include "stages/pipeline/stage_table.h"
#include "store/artifact_store.h"
#include "tools/bench/median_timer.h"

using namespace areagraph;

namespace {

double ProcessCpuMs() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) * 1e3 + static_cast<double>(now.tv_nsec) / 1e6;
}

// The compute of `stage` on the stored heads, as a callable run repeatedly.
std::function<void()> StageWork(ArtifactStore& store, const std::string& map,
                                const StageDefinition& stage, const proto::PipelineOptions& options,
                                std::vector<MessagePtr>* inputs) {
  if (stage.inputs.empty()) {  // import: the file, read and decoded
    const std::optional<MapRecord> record = store.ReadMap(map);
    if (!record || record->source_path.empty()) {
      throw InputError("map '" + map + "' has no source file in the store");
    }
    const std::string path = record->source_path;
    return [path, &options] { ImportGridMap(ReadImportSource(path), options.import()); };
  }
  if (stage.compute == nullptr) {
    throw InputError("stage '" + std::string(stage.info.name) +
                     "' reads its previous version; time it with ag-run instead");
  }
  for (const StageInfo& input : stage.inputs) {
    inputs->push_back(MessagePtr(StageOf(input).prototype->New()));
    ParseHeadArtifact(store, map, input, inputs->back().get(), nullptr);
  }
  return [&stage, &options, inputs] {
    std::vector<const google::protobuf::Message*> pointers;
    for (const MessagePtr& input : *inputs) pointers.push_back(input.get());
    // As the programs run it: freed heap goes back between its big steps.
    stage.compute(pointers, InputRelease([](size_t) {}, {}, ReturnFreedMemory), options);
  };
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Median CPU and wall milliseconds of one stage's compute on a stored map."};
  StageCommandLine flags;
  std::string stage_name;
  int repeat = 5;
  app.add_option("--store", flags.store_path, "SQLite artifact store")->capture_default_str();
  app.add_option("--map", flags.map_name, "map name")->required();
  app.add_option("--stage", stage_name, StageNameList())->required();
  app.add_option("--options", flags.options_file, "pipeline options (text format)");
  app.add_option("--set", flags.overrides, "option override key=value (repeatable)");
  app.add_option("--repeat", repeat, "runs of the compute")->check(CLI::Range(1, 1000));
  return RunCommand("ag-bench-stage", app, argc, argv, [&] {
    const proto::PipelineOptions options = LoadPipelineOptions(flags);
    const StageDefinition& stage = FindStage(stage_name, "--stage");
    auto store = OpenArtifactStore(flags.store_path, StoreMode::kReadOnly);
    std::vector<MessagePtr> inputs;
    const std::function<void()> work = StageWork(*store, flags.map_name, stage, options, &inputs);
    std::vector<double> cpu, wall;
    for (int run = 0; run < repeat; ++run) {
      const double cpu_start = ProcessCpuMs();
      wall.push_back(ElapsedMs(work));
      cpu.push_back(ProcessCpuMs() - cpu_start);
    }
    std::printf("%s %s cpu_ms %.2f wall_ms %.2f\n", flags.map_name.c_str(), stage.info.name,
                Median(cpu), Median(wall));
    return 0;
  });
}
