// ag-bench-live: feeds a running ag-live a simulated exploration over LCM and
// prints, per update, the time from ag-live's receipt of the grid to its
// publication of the graph, and how stable the ids are against the ground
// truth. A benchmark: it checks nothing. Run it through tools/bench-live.sh,
// which starts ag-live inside a private network namespace.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <lcm/lcm-cpp.hpp>
#include <opencv2/imgproc.hpp>
#include <regex>
#include <thread>

#include "common/error.h"
#include "common/text.h"
#include "runner/common/map_run.h"
#include "runner/live/area_graph_publisher.h"
#include "runner/live/lcm_connection.h"
#include "runner/live/lcm_conversion.h"
#include "runner/live/live_map_server.h"
#include "stages/common/command_line.h"
#include "stages/common/png_file.h"
#include "tools/bench/exploration_truth.h"
#include "tools/bench/id_stability.h"
#include "tools/bench/median_timer.h"
#include "tools/eval/label_image.h"
#include "tools/eval/map_evaluation.h"
#include "tools/example_maps/exploration.h"
#include "tools/export/area_label_image.h"

namespace areagraph {
namespace {

struct BenchFlags {
  ExplorationRun run;
  std::string url = kDefaultLcmUrl;
  std::string live_log;
  std::string scratch_dir = "/tmp";
  bool cold = true;
  double timeout_s = 900;
  std::string dump_dir;
  floorplan::ExplorationSettings exploration;
};

int64_t MicrosecondsNow() {
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// Waits for the area_graph_t of `name` made from the grid of `map_utime`.
class GraphWaiter {
 public:
  GraphWaiter(lcm::LCM& lcm, const std::string& url) : lcm_(lcm), url_(url) {
    lcm_.subscribe(kAreaGraphChannel, &GraphWaiter::OnGraph, this);
    StartReceiving(lcm_, url_);
  }
  areagraph_lcm::area_graph_t Wait(const std::string& name, int64_t map_utime, double timeout_s) {
    const auto give_up = std::chrono::steady_clock::now() +
                         std::chrono::milliseconds(static_cast<int64_t>(timeout_s * 1000));
    while (std::chrono::steady_clock::now() < give_up) {
      HandleOneMessage(lcm_, 100, url_);
      if (got_ && last_.map_name == name && last_.map_utime == map_utime) return last_;
    }
    throw Error("no Area Graph for '" + name + "' within " + FormatNumber(timeout_s) +
                " s; is ag-live running (tools/bench-live.sh starts it)?");
  }

 private:
  void OnGraph(const lcm::ReceiveBuffer* buffer, const std::string&) {
    last_ = DecodeAreaGraphMessage(buffer->data, static_cast<int>(buffer->data_size));
    got_ = true;
  }
  lcm::LCM& lcm_;
  std::string url_;
  areagraph_lcm::area_graph_t last_;
  bool got_ = false;
};

// ag-live's own figure for the graph with key `key`: "published N ms after
// receipt" on its line in `log` (it writes the line right after publishing).
double ReceiptToPublicationMs(const std::string& log, const std::string& key) {
  if (log.empty()) return -1;
  const std::regex line(".* key " + key.substr(0, 12) + ", .*published (\\d+) ms after receipt");
  for (int attempt = 0; attempt < 50; ++attempt) {
    std::ifstream in(log);
    double found = -1;
    for (std::string text; std::getline(in, text);) {
      std::smatch match;
      if (std::regex_match(text, match, line)) found = std::stod(match[1].str());
    }
    if (found >= 0) return found;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return -1;
}

// The whole pipeline on `grid` in a new store, in process, as ag-live runs
// it: what a cold run of this map costs.
double ColdPipelineMs(const proto::GridMap& grid, const std::string& scratch_dir) {
  const std::string path = scratch_dir + "/ag-bench-live-cold.db";
  std::remove(path.c_str());
  std::remove((path + "-wal").c_str());
  std::remove((path + "-shm").c_str());
  double elapsed = 0;
  {
    const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(path);
    FailureLog failures(*store);
    const std::string digest = LiveGridDigest(grid);
    MapImport map_import;
    map_import.read_inputs = [&] {
      StageInputs inputs;
      inputs.digests = {digest};
      return inputs;
    };
    map_import.decode = [&] { return std::make_unique<proto::GridMap>(grid); };
    elapsed = ElapsedMs([&] {
      RunOneMap(*store, failures, "cold", "", map_import, proto::PipelineOptions(),
                MapRunSettings(), PipelineObserver(), nullptr);
    });
  }
  std::remove(path.c_str());
  return elapsed;
}

// Writes step `step` into `dir` for scoring with ag-eval outside the bench:
// grid/<name>_NN.png (the grid sent, grey as ag-import reads it),
// live/<name>_NN.png (the published graph's areas, 16-bit labels) and
// gt/<name>_NN.png (the ground-truth rooms cropped to the grid and to what was
// seen, 16-bit labels).
void DumpStep(const std::string& dir, const std::string& name, int step,
              const floorplan::ExplorationMap& map, const proto::AreaGraph& published,
              const cv::Mat& gt_rooms) {
  char file[300];
  std::snprintf(file, sizeof(file), "/%s_%02d.png", name.c_str(), step);
  cv::Mat grey(map.cells.size(), CV_8U, cv::Scalar(205));
  grey.setTo(254, map.cells == floorplan::kFreeCell);
  grey.setTo(0, map.cells == floorplan::kOccupiedCell);
  WritePngFile(dir + "/grid" + file, grey);
  WritePngFile(dir + "/live" + file, AreaLabelImage(published));
  cv::Mat gt;
  SeenGroundTruth(map, gt_rooms).convertTo(gt, CV_16U);
  WritePngFile(dir + "/gt" + file, gt);
}

std::string Percent(int part, int whole) {
  if (whole == 0) return "-";
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f %%", 100.0 * part / whole);
  return text;
}

int RunBench(const BenchFlags& flags) {
  if (flags.run.name.empty()) throw OptionsError("--name is required");
  if ((flags.run.generated_m > 0) == !flags.run.map_path.empty()) {
    throw OptionsError("give either --map and --gt, or --generated");
  }
  if (!flags.run.map_path.empty() && flags.run.gt_path.empty())
    throw OptionsError("--map needs --gt");
  if (!flags.dump_dir.empty()) {
    for (const char* sub : {"/grid", "/live", "/gt"}) {
      std::filesystem::create_directories(flags.dump_dir + sub);
    }
  }
  const ExplorationTruth truth = LoadExplorationTruth(flags.run.map_path, flags.run.gt_path,
                                                      flags.run.generated_m, flags.run.seed);
  floorplan::ExplorationSettings settings = flags.exploration;
  settings.steps = flags.run.steps;
  settings.seed = flags.run.seed;
  std::cerr << "ag-bench-live: " << flags.run.name << ": " << truth.cells.cols << "x"
            << truth.cells.rows << " px, " << CountSegments(truth.rooms)
            << " ground-truth rooms; planning the exploration" << std::endl;
  floorplan::Exploration exploration(truth.cells, settings);
  std::cerr << "ag-bench-live: " << flags.run.name << ": " << exploration.scans() << " scans in "
            << flags.run.steps << " steps, then " << flags.run.noise_steps << " noise-only updates"
            << std::endl;

  const std::string url = ReceivingLcmUrl(flags.url);
  const std::unique_ptr<lcm::LCM> lcm = OpenLcm(url);
  GraphWaiter waiter(*lcm, url);
  std::printf(
      "| step | seen | grid px | areas | version | receipt to publication ms | round trip ms | "
      "cold ms | update / cold | GT-tracked areas kept | ids kept |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|\n");
  GroundTruthView previous;
  IdStability explored_total, noise_total;
  std::vector<double> ratios;
  const double free_cells = cv::countNonZero(truth.cells == floorplan::kFreeCell);
  for (int step = 1; step <= flags.run.steps + flags.run.noise_steps; ++step) {
    const uint32_t noise_seed = flags.run.seed * 1000 + static_cast<uint32_t>(step);
    const floorplan::ExplorationMap map = step <= flags.run.steps
                                              ? exploration.MapAfter(step, noise_seed)
                                              : exploration.MapAgain(noise_seed);
    const proto::GridMap grid = ExplorationGridMap(map, truth.cells.rows);
    const int64_t utime = MicrosecondsNow();
    const areagraph_lcm::grid_map_t message = ToLcmGridMap(flags.run.name, utime, grid);
    const auto sent = std::chrono::steady_clock::now();
    if (lcm->publish(kGridMapChannel, &message) != 0) throw Error("cannot publish on MAP");
    const areagraph_lcm::area_graph_t published =
        waiter.Wait(flags.run.name, utime, flags.timeout_s);
    const double round_trip =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - sent).count();
    const double live_ms = ReceiptToPublicationMs(flags.live_log, published.artifact_key);
    const double cold_ms = flags.cold ? ColdPipelineMs(grid, flags.scratch_dir) : -1;
    const proto::AreaGraph published_graph = AreaGraphFromLcm(published);
    const GroundTruthView view = ViewAgainstGroundTruth(published_graph, truth.rooms, map.seen);
    if (!flags.dump_dir.empty()) {
      DumpStep(flags.dump_dir, flags.run.name, step, map, published_graph, truth.rooms);
    }
    std::string tracked = "-", kept = "-";
    if (step > 1) {
      const IdStability stability = CompareViews(previous, view);
      IdStability& total = step <= flags.run.steps ? explored_total : noise_total;
      total += stability;
      tracked = std::to_string(stability.kept) + " / " + std::to_string(stability.tracked);
      kept = Percent(stability.ids_kept, stability.ids_before);
    }
    std::string ratio = "-";
    if (cold_ms > 0 && live_ms >= 0) {
      ratios.push_back(live_ms / cold_ms);
      char text[32];
      std::snprintf(text, sizeof(text), "%.2f", live_ms / cold_ms);
      ratio = text;
    }
    std::printf(
        "| %d%s | %.0f %% | %dx%d | %d | %lld | %.0f | %.0f | %.0f | %s | %s | %s |\n", step,
        step > flags.run.steps ? " (noise)" : "",
        100.0 * cv::countNonZero(map.seen & (truth.cells == floorplan::kFreeCell)) / free_cells,
        grid.frame().width_px(), grid.frame().height_px(), published.num_areas,
        static_cast<long long>(published.version), live_ms, round_trip, cold_ms, ratio.c_str(),
        tracked.c_str(), kept.c_str());
    std::fflush(stdout);
    std::cerr << "ag-bench-live: " << flags.run.name << ": step " << step << " done" << std::endl;
    previous = view;
  }
  std::printf(
      "\n%s: over the exploration, %s of the areas whose ground-truth room was fully seen in "
      "both updates kept their id (%d of %d); over the noise-only updates %s (%d of %d), and "
      "%s of all ids stayed (by the earlier test that also wants the id's area still to have "
      "half of its cells in the room: %s and %s). Update / cold: median %.2f, max %.2f.\n\n",
      flags.run.name.c_str(), Percent(explored_total.kept, explored_total.tracked).c_str(),
      explored_total.kept, explored_total.tracked,
      Percent(noise_total.kept, noise_total.tracked).c_str(), noise_total.kept, noise_total.tracked,
      Percent(noise_total.ids_kept, noise_total.ids_before).c_str(),
      Percent(explored_total.kept_same_room, explored_total.tracked).c_str(),
      Percent(noise_total.kept_same_room, noise_total.tracked).c_str(), Median(ratios),
      ratios.empty() ? 0 : *std::max_element(ratios.begin(), ratios.end()));
  return 0;
}

}  // namespace
}  // namespace areagraph

int main(int argc, char** argv) {
  using namespace areagraph;
  CLI::App app{
      "Feeds a running ag-live (same LCM URL) a simulated exploration: a robot with a 360-degree "
      "8 m range sensor explores the map frontier by frontier; its path is cut into --steps "
      "growing maps, each with fresh scan noise and cropped to what was seen (so the grid grows "
      "and moves), then --noise-steps more with only new noise. Prints a Markdown row per "
      "update: ag-live's time from receipt to publication (from --live-log), the round trip, "
      "the cold pipeline time of the same grid in a new store, and how many areas whose "
      "ground-truth room was fully seen in both updates kept their id. Run it through "
      "tools/bench-live.sh."};
  BenchFlags flags;
  AddExplorationRunOptions(app, flags.run, "map name sent to ag-live");
  app.add_option("--wall-noise", flags.exploration.wall_noise,
                 "chance that a free cell next to a wall turns occupied, per map")
      ->capture_default_str();
  app.add_option("--frontier-noise", flags.exploration.frontier_noise,
                 "chance that a free cell next to unseen space turns unknown, per map")
      ->capture_default_str();
  app.add_option("--speckles", flags.exploration.speckles_per_m2,
                 "one-cell obstacles per square metre of free space, per map")
      ->capture_default_str();
  app.add_option("--url", flags.url, "LCM URL (ttl=0)")->capture_default_str();
  app.add_option("--live-log", flags.live_log, "ag-live's standard output, to read its timings");
  app.add_option("--scratch", flags.scratch_dir, "folder for the cold runs' store")
      ->capture_default_str();
  app.add_flag("!--no-cold", flags.cold, "skip the cold pipeline runs");
  app.add_option("--dump", flags.dump_dir,
                 "also write each update into this folder: grid/<name>_NN.png (the grid sent), "
                 "live/<name>_NN.png (the published areas as 16-bit labels) and gt/<name>_NN.png "
                 "(the ground truth cropped to the grid and to what was seen), to score with "
                 "ag-eval");
  app.add_option("--timeout", flags.timeout_s, "seconds to wait for each graph")
      ->capture_default_str();
  return RunCommand("ag-bench-live", app, argc, argv, [&] { return RunBench(flags); });
}
