// ag-run: the whole pipeline for one map or a collection, through the cache,
// with parallel worker processes, failures recorded, and an optional LCM
// publisher for live consumers.
#include <CLI/CLI.hpp>
#include <iostream>

#include "runner/run/collection_run.h"
#include "stages/common/command_line.h"
#include "stages/common/pipeline_options.h"
#include "stages/pipeline/stage_table.h"
#include "tools/report/run_report_writer.h"

int main(int argc, char** argv) {
  using namespace areagraph;
  CLI::App app{
      "Runs the whole pipeline (" + StageNameList() +
      ") for maps through the store's cache: a stage whose cache key is stored does no work. MAP "
      "is an image (with its map_server YAML beside it), a directory searched recursively for "
      "images, or a manifest (.tsv/.csv with columns path, name and option keys such as "
      "cut.room_width_m). A map that fails is recorded in the store (ag-inspect --failures) and "
      "the others go on; the exit status is 1 when any map failed."};
  RunFlags flags;
  AddRunFlags(app, flags);
  std::string report_dir;
  app.add_option("--report", report_dir,
                 "then write DIR/index.html (a table of the maps) and DIR/maps/<map>.html (each "
                 "map's viewer page, as ag-export --format html writes it); with no MAP, only "
                 "the report of every map in --store (also a collection index), nothing run")
      ->type_name("DIR");
  return RunCommand("ag-run", app, argc, argv, [&] {
    if (flags.maps.empty() && !report_dir.empty() && !flags.print_options) {
      WriteRunReport(flags, report_dir);
      return 0;
    }
    CheckRunFlags(app, flags);
    if (flags.print_options) {  // examples/options/default.pbtxt is this output
      std::cout << CanonicalText(LoadPipelineOptions(flags.stage));
      return 0;
    }
    const int status = RunCollection(flags);
    if (!report_dir.empty()) WriteRunReport(flags, report_dir);
    return status;
  });
}
