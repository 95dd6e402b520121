// ag-bench-match: how stable ag-match keeps the ids of a simulated
// exploration under several sets of match options, without LCM and without
// re-running the segmentation: the merge graph of each update is computed
// once (or read from --cache), then each variant's chain of match versions
// is replayed in process. Prints one Markdown row per variant: the id
// stability of tools/bench-live.sh (same exploration, seeds and noise) and
// the MCC of the published graphs against the ground truth seen so far. A
// benchmark for choosing match's constants: it checks nothing.
#include <google/protobuf/text_format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>

#include "common/error.h"
#include "stages/common/command_line.h"
#include "stages/common/png_file.h"
#include "stages/common/stage_info.h"
#include "stages/match/area_cells.h"
#include "stages/match/area_graph_matching.h"
#include "stages/match/join_undoing.h"
#include "stages/pipeline/stage_table.h"
#include "tools/bench/exploration_truth.h"
#include "tools/bench/id_stability.h"
#include "tools/eval/label_image.h"
#include "tools/eval/map_evaluation.h"
#include "tools/export/area_label_image.h"
#include "tools/render/artifact_drawing.h"

namespace areagraph {
namespace {

struct MatchBenchFlags {
  ExplorationRun run;
  std::string cache_dir;
  std::vector<std::string> variants;
  bool per_step = false;
  std::string dump_dir;
  bool reuse = false;
  floorplan::ExplorationSettings exploration;
};

// One update of the exploration: what match needs and what it is scored on.
struct Update {
  proto::AreaGraph merged;
  cv::Mat seen;     // whole map, as ExplorationMap::seen
  cv::Mat seen_gt;  // SeenGroundTruth
  bool noise_only = false;
  proto::GridMap grid;  // only with --dump
};

// The merge artifact of `grid` with default options, every stage before
// match run in memory through the stage table, as ag-live runs them.
proto::AreaGraph MergedGraph(const proto::GridMap& grid) {
  const proto::PipelineOptions options;
  std::map<std::string, MessagePtr> artifacts;
  artifacts[kImportStage.name] = std::make_unique<proto::GridMap>(grid);
  for (const StageDefinition& stage : StageTable()) {
    if (stage.compute == nullptr) continue;  // import and match
    std::vector<const google::protobuf::Message*> inputs;
    for (const StageInfo& input : stage.inputs) inputs.push_back(artifacts.at(input.name).get());
    artifacts[stage.info.name] = stage.compute(
        inputs, [](size_t) {}, options);
    if (std::string(stage.info.name) == kMergeStage.name) {
      return static_cast<const proto::AreaGraph&>(*artifacts[stage.info.name]);
    }
  }
  throw Error("the stage table has no merge stage");
}

// The merge graph of one update, from the cache folder when it holds it.
proto::AreaGraph CachedMergedGraph(const MatchBenchFlags& flags, int step,
                                   const proto::GridMap& grid) {
  std::string path;
  if (!flags.cache_dir.empty()) {
    char file[300];
    std::snprintf(file, sizeof(file), "/%s-seed%u-merge%d-%02d.pb", flags.run.name.c_str(),
                  flags.run.seed, kMergeStage.version, step);
    path = flags.cache_dir + file;
    std::ifstream in(path, std::ios::binary);
    proto::AreaGraph graph;
    if (in && graph.ParseFromIstream(&in)) return graph;
  }
  proto::AreaGraph graph = MergedGraph(grid);
  if (!path.empty()) {
    std::ofstream out(path, std::ios::binary);
    graph.SerializeToOstream(&out);
  }
  return graph;
}

std::vector<Update> ExploreAndSegment(const MatchBenchFlags& flags, const ExplorationTruth& truth) {
  floorplan::ExplorationSettings settings = flags.exploration;
  settings.steps = flags.run.steps;
  settings.seed = flags.run.seed;
  floorplan::Exploration exploration(truth.cells, settings);
  std::vector<Update> updates;
  for (int step = 1; step <= flags.run.steps + flags.run.noise_steps; ++step) {
    const uint32_t noise_seed = flags.run.seed * 1000 + static_cast<uint32_t>(step);
    const floorplan::ExplorationMap map = step <= flags.run.steps
                                              ? exploration.MapAfter(step, noise_seed)
                                              : exploration.MapAgain(noise_seed);
    Update update;
    update.merged = CachedMergedGraph(flags, step, ExplorationGridMap(map, truth.cells.rows));
    update.seen = map.seen.clone();
    update.seen_gt = SeenGroundTruth(map, truth.rooms);
    update.noise_only = step > flags.run.steps;
    if (!flags.dump_dir.empty() || flags.reuse) {
      update.grid = ExplorationGridMap(map, truth.cells.rows);
    }
    updates.push_back(std::move(update));
    std::cerr << "ag-bench-match: " << flags.run.name << ": step " << step << " segmented"
              << std::endl;
  }
  return updates;
}

// Why one tracked id was lost (--per-step), counted per variant.
struct LossCounts {
  std::map<std::string, int> by_kind;
};

// The share of an area's cells that lie in `room`, as a percentage.
double RoomPercent(const GroundTruthView::RoomShare& share) {
  return 100.0 * share.room_cells / std::max<int64_t>(1, share.cells);
}

// Says on stderr where the tracked areas of `before` went that lost their id
// in `after` (`lost`, see CompareViews; --per-step),
// and counts each kind of loss in `counts`: "id moved" (the id is still
// there but on an area that holds less than half of the area's cells in its
// room),
// "joined" (most of its cells went to an area that kept another old id;
// with the conditions of match's join undoing: size, share inside, passage),
// "new id" and "gone".
void ExplainLosses(const proto::AreaGraph& before, const GroundTruthView& before_view,
                   const proto::AreaGraph& after, const GroundTruthView& after_view,
                   const std::set<int>& lost, const proto::MatchOptions& options, int step,
                   LossCounts& counts) {
  const AreaCells old_cells = RasterizeAreas(before, after.frame());
  const AreaCells new_cells = RasterizeAreas(after, after.frame());
  const std::vector<AreaOverlap> overlaps = CountOverlaps(old_cells, new_cells);
  std::map<int, int> index_of_id, old_index_of_id;
  for (int i = 0; i < after.areas_size(); ++i) index_of_id[after.areas(i).stable_id()] = i;
  for (int i = 0; i < before.areas_size(); ++i) old_index_of_id[before.areas(i).stable_id()] = i;
  std::set<std::pair<int, int>> linked;
  for (const proto::Passage& passage : before.passages()) {
    linked.insert({passage.area_a(), passage.area_b()});
    linked.insert({passage.area_b(), passage.area_a()});
  }
  for (int id : lost) {
    const int b = old_index_of_id.at(id);
    const int room = before_view.room_of_area.at(id);
    const GroundTruthView::RoomShare& was = before_view.share_of_area.at(id);
    std::fprintf(stderr,
                 "  step %d: id %d (%.1f m2, room %d: %.0f %% of its cells, %.0f %% labelled)",
                 step, id, before.areas(b).area_m2(), room, RoomPercent(was),
                 100.0 * was.labelled_cells / std::max<int64_t>(1, was.cells));
    std::map<int, int64_t> shared;  // index in after -> cells of b
    for (const AreaOverlap& pair : overlaps) {
      if (pair.before == b) shared[pair.after] = pair.cells;
    }
    const auto same = index_of_id.find(id);
    if (same != index_of_id.end()) {
      const GroundTruthView::RoomShare& is = after_view.share_of_area.at(id);
      std::fprintf(stderr,
                   " kept its id on %.1f m2 holding only %.0f %% of its cells (largest room %d, "
                   "%.0f %% of the cells)\n",
                   after.areas(same->second).area_m2(),
                   100.0 * shared[same->second] / std::max<int64_t>(1, old_cells.cells[b]), is.room,
                   RoomPercent(is));
      ++counts.by_kind["id moved"];
      continue;
    }
    int best = -1;
    int64_t best_cells = 0;
    for (const auto& [a, cells] : shared) {
      if (cells > best_cells) {
        best = a;
        best_cells = cells;
      }
    }
    if (best < 0) {
      std::fprintf(stderr, " gone\n");
      ++counts.by_kind["gone"];
      continue;
    }
    const proto::Area& into = after.areas(best);
    const double inside = 100.0 * best_cells / std::max<int64_t>(1, old_cells.cells[b]);
    const auto kept = old_index_of_id.find(into.stable_id());
    if (kept == old_index_of_id.end()) {
      std::fprintf(stderr, " lost: %.0f %% of it in new id %d (%.1f m2)\n", inside,
                   into.stable_id(), into.area_m2());
      ++counts.by_kind["new id"];
      continue;
    }
    const bool passage = linked.count({kept->second, b}) > 0;
    std::fprintf(stderr, " joined: %.0f %% of it in id %d (%.1f m2, was %.1f m2), %s\n", inside,
                 into.stable_id(), into.area_m2(), before.areas(kept->second).area_m2(),
                 passage ? "a passage between them" : "no passage between them");
    std::string kind = "joined";
    if (!passage) {
      kind += ", no passage";
    } else if (inside < 100 * options.min_overlap()) {
      kind += ", under the share inside";
    } else if (before.areas(b).area_m2() >= options.split_joins_below_m2()) {
      kind += ", too large";
    } else {
      kind += ", cut refused";
    }
    ++counts.by_kind[kind];
  }
}

std::string Percent(int part, int whole) {
  if (whole == 0) return "-";
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f %% (%d / %d)", 100.0 * part / whole, part, whole);
  return text;
}

// Writes the published graph of one update over its grid (--dump), as
// ag-render draws a match artifact: areas by stable id, passages in red.
void DumpGraph(const MatchBenchFlags& flags, const Update& update, const proto::AreaGraph& graph,
               int step) {
  const proto::MapFrame& frame = update.grid.frame();
  Canvas canvas(update.grid.cells(), frame.width_px(), frame.height_px(),
                DefaultScale(frame.width_px(), frame.height_px()));
  DrawAreaGraph(graph, canvas);
  char file[300];
  std::snprintf(file, sizeof(file), "/%s-%02d.png", flags.run.name.c_str(), step);
  WritePngFile(flags.dump_dir + file, canvas.image());
}

// Replays the updates through match with `options` and prints its row.
void ReplayVariant(const MatchBenchFlags& flags, const std::vector<Update>& updates,
                   const cv::Mat& rooms, const std::string& variant_text) {
  proto::MatchOptions options;
  if (!google::protobuf::TextFormat::ParseFromString(variant_text, &options)) {
    throw OptionsError("--variant '" + variant_text + "' is not MatchOptions in text format");
  }
  proto::AreaGraph previous;
  GroundTruthView previous_view;
  IdStability explored, noise;
  LossCounts losses;
  std::vector<double> mccs;
  for (size_t i = 0; i < updates.size(); ++i) {
    VersionLink link;
    if (i > 0) link = {"version-" + std::to_string(i), static_cast<int64_t>(i + 1)};
    const proto::AreaGraph matched =
        MatchAreaGraph(updates[i].merged, i > 0 ? &previous : nullptr, link, options, "bench");
    const GroundTruthView view = ViewAgainstGroundTruth(matched, rooms, updates[i].seen);
    if (i > 0) {
      const IdStability step = CompareViews(previous_view, view);
      (updates[i].noise_only ? noise : explored) += step;
      if (flags.per_step && !step.lost.empty()) {
        ExplainLosses(previous, previous_view, matched, view, step.lost, options,
                      static_cast<int>(i + 1), losses);
      }
    }
    if (!flags.dump_dir.empty() && variant_text == flags.variants.front()) {
      DumpGraph(flags, updates[i], matched, static_cast<int>(i + 1));
    }
    cv::Mat labels;
    AreaLabelImage(matched).convertTo(labels, CV_32S);
    mccs.push_back(ScoreLabelImages(labels, updates[i].seen_gt, MccVariant::kMaoris).mcc);
    previous = matched;
    previous_view = view;
  }
  if (flags.per_step) {
    std::fprintf(stderr,
                 "  losses of %s:", variant_text.empty() ? "(defaults)" : variant_text.c_str());
    for (const auto& [kind, count] : losses.by_kind)
      std::fprintf(stderr, " %s %d;", kind.c_str(), count);
    std::fprintf(stderr, "\n");
    std::fprintf(stderr, "  MCC per update:");
    for (double mcc : mccs) std::fprintf(stderr, " %.3f", mcc);
    std::fprintf(stderr, "\n");
  }
  double mean = 0;
  for (double mcc : mccs) mean += mcc / mccs.size();
  std::printf("| %s | %s | %s | %s | %s | %s | %.3f | %.3f | %d |\n", flags.run.name.c_str(),
              variant_text.empty() ? "(defaults)" : variant_text.c_str(),
              Percent(explored.kept, explored.tracked).c_str(),
              Percent(noise.kept, noise.tracked).c_str(),
              Percent(explored.kept_same_room, explored.tracked).c_str(),
              Percent(noise.kept_same_room, noise.tracked).c_str(), mccs.back(), mean,
              previous.areas_size());
  std::fflush(stdout);
}

// The cells of `grid` in the whole map's frame (CV_8U, 255 where the grid
// does not reach).
cv::Mat WholeMapCells(const proto::GridMap& grid, cv::Size whole) {
  cv::Mat cells(whole, CV_8U, cv::Scalar(255));
  const proto::MapFrame& frame = grid.frame();
  const int x0 = static_cast<int>(std::lround(frame.origin_x_m() / frame.resolution_m()));
  const int y_bottom = static_cast<int>(std::lround(frame.origin_y_m() / frame.resolution_m()));
  const int y0 = whole.height - y_bottom - frame.height_px();
  const cv::Mat own(frame.height_px(), frame.width_px(), CV_8U,
                    const_cast<char*>(grid.cells().data()));
  own.copyTo(cells(cv::Rect(x0, y0, frame.width_px(), frame.height_px())));
  return cells;
}

// The merge areas of `graph` as text (polygon in metres), to find areas that
// came out bit for bit the same in two updates.
std::multiset<std::string> AreaPolygons(const proto::AreaGraph& graph) {
  std::multiset<std::string> polygons;
  for (const proto::Area& area : graph.areas()) {
    polygons.insert(area.polygon_m().SerializeAsString());
  }
  return polygons;
}

// --reuse: per update, how much of the previous update a stage could reuse
// if it recomputed only what changed: the share of the previous grid's cells
// that are the same, and the share of merge's areas that are bit for bit an
// area of the previous merge graph. Every changed grid is a full run today.
void PrintReuse(const std::vector<Update>& updates, cv::Size whole) {
  std::printf(
      "\n| step | grid cells as before | merge areas as before (same polygon) |\n"
      "|---|--:|--:|\n");
  for (size_t i = 1; i < updates.size(); ++i) {
    const cv::Mat before = WholeMapCells(updates[i - 1].grid, whole);
    const cv::Mat after = WholeMapCells(updates[i].grid, whole);
    const cv::Mat had = before != 255;
    const int same = cv::countNonZero((before == after) & had);
    const std::multiset<std::string> old_areas = AreaPolygons(updates[i - 1].merged);
    int kept = 0;
    for (const std::string& polygon : AreaPolygons(updates[i].merged))
      kept += old_areas.count(polygon) > 0;
    std::printf("| %zu%s | %.1f %% | %d / %d |\n", i + 1, updates[i].noise_only ? " (noise)" : "",
                100.0 * same / std::max(1, cv::countNonZero(had)), kept,
                updates[i].merged.areas_size());
  }
}

int RunBench(MatchBenchFlags flags) {
  if (flags.run.name.empty()) throw OptionsError("--name is required");
  if ((flags.run.generated_m > 0) == !flags.run.map_path.empty()) {
    throw OptionsError("give either --map and --gt, or --generated");
  }
  if (!flags.run.map_path.empty() && flags.run.gt_path.empty())
    throw OptionsError("--map needs --gt");
  if (!flags.cache_dir.empty()) std::filesystem::create_directories(flags.cache_dir);
  if (!flags.dump_dir.empty()) std::filesystem::create_directories(flags.dump_dir);
  if (flags.variants.empty()) flags.variants.push_back("");
  const ExplorationTruth truth = LoadExplorationTruth(flags.run.map_path, flags.run.gt_path,
                                                      flags.run.generated_m, flags.run.seed);
  std::cerr << "ag-bench-match: " << flags.run.name << ": " << truth.cells.cols << "x"
            << truth.cells.rows << " px, " << CountSegments(truth.rooms) << " ground-truth rooms"
            << std::endl;
  const std::vector<Update> updates = ExploreAndSegment(flags, truth);
  for (const std::string& variant : flags.variants) {
    ReplayVariant(flags, updates, truth.rooms, variant);
  }
  if (flags.reuse) PrintReuse(updates, truth.cells.size());
  return 0;
}

}  // namespace
}  // namespace areagraph

int main(int argc, char** argv) {
  using namespace areagraph;
  CLI::App app{
      "Replays the simulated exploration of ag-bench-live (same maps, seeds and noise) through "
      "ag-match under each --variant of the match options, in process and without LCM: the "
      "stages up to merge run once per update (or come from --cache), match runs once per "
      "variant and update. Prints a Markdown row per variant: of the areas whose ground-truth "
      "room was fully seen in two consecutive updates, how many kept their id, over the "
      "exploration and over the noise-only updates (as tools/bench-live.sh counts them), and the "
      "MCC (MAORIS variant) of the published graphs against the ground truth seen so far, at "
      "the last update and the mean over all. For choosing match's constants; checks nothing."};
  MatchBenchFlags flags;
  AddExplorationRunOptions(app, flags.run, "map name (labels the rows and the cache files)");
  app.add_option("--cache", flags.cache_dir,
                 "folder that keeps each update's merge graph between runs (by name, seed, merge "
                 "version and step; delete it when the stages before match change)");
  app.add_option("--variant", flags.variants,
                 "match options in text format, e.g. 'fold_fragments_below_m2: 0'; repeat for "
                 "more rows (default: one row with the defaults)");
  app.add_flag("--per-step", flags.per_step,
               "print on stderr where each lost id went, and the losses of each kind per variant");
  app.add_flag("--reuse", flags.reuse,
               "also print, per update, the share of grid cells and of merge areas that are as "
               "in the update before (what a stage that recomputed only changes could reuse)");
  app.add_option("--dump", flags.dump_dir,
                 "folder for a picture of each update's published graph under the first variant "
                 "(NAME-STEP.png: areas coloured and labelled by stable id, passages red)");
  return RunCommand("ag-bench-match", app, argc, argv, [&] { return RunBench(flags); });
}
