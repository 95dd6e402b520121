#include "runner/run/run_command_line.h"

#include <algorithm>
#include <thread>

#include "common/error.h"
#include "runner/live/lcm_connection.h"
#include "stages/pipeline/stage_table.h"

namespace areagraph {

void AddRunFlags(CLI::App& app, RunFlags& flags) {
  flags.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  app.add_option("--store", flags.stage.store_path, "artifact store (SQLite file)")
      ->capture_default_str();
  app.add_option("--options", flags.stage.options_file, "pipeline options (protobuf text format)");
  // One value per --set: MAP is optional (--print-options), so a greedy
  // --set would take the maps too.
  app.add_option("--set", flags.stage.overrides, "override one option: stage.field=value")
      ->allow_extra_args(false);
  CLI::Option* from = app.add_option("--from", flags.from_stage,
                                     "start at this stage; earlier stages' heads are its inputs");
  app.add_option("--only", flags.only_stage, "run this stage only")->excludes(from);
  app.add_flag("--force", flags.stage.force, "recompute even when the cache holds the result");
  app.add_option("--jobs,-j", flags.jobs, "maps processed in parallel (worker processes)")
      ->capture_default_str();
  app.add_option("--threads-per-map", flags.threads_per_map,
                 "threads each map's stages may use (OpenCV's pool); 0 gives every worker process "
                 "an equal share of the cores: max(1, cores / workers), workers being the smaller "
                 "of --jobs and the number of maps")
      ->capture_default_str();
  app.add_option("--shard", flags.shard,
                 "K/N: run only the maps whose name hashes to K modulo N (0 <= K < N)");
  app.add_flag("--publish", flags.publish,
               "publish each new or changed Area Graph on LCM channel AREA_GRAPH (at --url)");
  AddLcmUrlFlag(app, flags.url);
  app.add_flag("--json", flags.json, "print the summary as JSON");
  app.add_option("MAP", flags.maps, "map image, directory or manifest");
  app.add_flag("--print-options", flags.print_options,
               "print the options a run would use (the --options file with every --set, every "
               "default filled in) in protobuf text format and exit; no MAP");
}

void CheckRunFlags(const CLI::App& app, const RunFlags& flags) {
  if (flags.maps.empty() != flags.print_options) {
    throw OptionsError(flags.print_options ? "--print-options takes no MAP"
                                           : "MAP is required (see --help)");
  }
  if (app.get_option("--url")->count() > 0 && !flags.publish) {
    throw OptionsError("--url is where --publish sends; add --publish, or drop --url");
  }
  if (flags.jobs < 1 || flags.jobs > 1024) {
    throw OptionsError("--jobs " + std::to_string(flags.jobs) + " must be between 1 and 1024");
  }
  if (flags.threads_per_map < 0 || flags.threads_per_map > 1024) {
    throw OptionsError("--threads-per-map " + std::to_string(flags.threads_per_map) +
                       " must be between 0 (a share of the cores) and 1024");
  }
}

RunSettings SettingsFrom(const RunFlags& flags) {
  RunSettings settings;
  settings.store_path = flags.stage.store_path;
  settings.map.force = flags.stage.force;
  if (!flags.from_stage.empty()) settings.map.first = FindStage(flags.from_stage, "--from").info;
  if (!flags.only_stage.empty()) {
    settings.map.first = settings.map.last = FindStage(flags.only_stage, "--only").info;
  }
  return settings;
}

}  // namespace areagraph
