#include "stages/merge/merge_passes.h"

#include <algorithm>

#include "stages/common/skipped_passes.h"
#include "stages/merge/bay_folding.h"
#include "stages/merge/closed_rooms.h"
#include "stages/merge/corridor_joining.h"
#include "stages/merge/corridor_piece_folding.h"
#include "stages/merge/corridor_stem_joining.h"
#include "stages/merge/furniture_gap_joining.h"
#include "stages/merge/furniture_rows.h"
#include "stages/merge/porous_border_joining.h"
#include "stages/merge/room_joining.h"
#include "stages/merge/split_corridor_joining.h"

namespace areagraph {
namespace {

using Options = proto::MergeOptions;
using google::protobuf::Message;

std::vector<MergePass> MakeTable() {
  std::vector<MergePass> table;
  table.push_back({
      Options::JOIN_CORRIDOR_PIECES,
      "first: the Topology Graph cuts a corridor at every side door, and the passes after it "
      "measure a corridor's shape on the whole of it",
      nullptr,
      [](const MergeInput& in, const PlanModel&, AreaPlan* plan) {
        JoinCorridorPieces(in.graph, plan);
      },
      nullptr,
  });
  table.push_back({
      Options::JOIN_ROOMS_WITHOUT_DOORS,
      "before the other room joins: a room the disk split at furniture or a bend is one room "
      "again before its size and openings are weighed",
      nullptr,
      [](const MergeInput& in, const PlanModel& model, AreaPlan* plan) {
        JoinRoomsWithoutDoors(in.graph, model, in.closed, plan);
      },
      nullptr,
  });
  table.push_back({
      Options::JOIN_FURNITURE_GAPS,
      "after the rooms are whole: its size limit is for the strip beside a desk, not for a "
      "piece of a room",
      [](const Options& o) -> const Message* { return &o.furniture_gaps(); },
      [](const MergeInput& in, const PlanModel& model, AreaPlan* plan) {
        const proto::JoinFurnitureGapsOptions& options = in.options.furniture_gaps();
        // Islands are looked for only at the openings' jambs.
        const IslandsAt islands_at = [&](const std::vector<cv::Point>& cells) {
          return FurnitureIslandsAt(in.map, in.graph.island_max_length_m(), /*fill_outlines=*/true,
                                    options.max_elongation(), cells);
        };
        JoinAreasAtFurnitureGaps(in.graph, model, in.closed, islands_at,
                                 in.options.corridor_pieces().below_m2(), plan);
      },
      nullptr,
  });
  table.push_back({
      Options::JOIN_FURNITURE_ROWS,
      "with the furniture gaps, and with their limits: a stack of rows is furniture as an "
      "island is, only too long for one",
      nullptr,
      [](const MergeInput& in, const PlanModel& model, AreaPlan* plan) {
        JoinAreasAtFurnitureRows(in.graph, model, in.furniture_rows, in.closed,
                                 in.options.corridor_pieces().below_m2(), plan);
      },
      nullptr,
  });
  table.push_back({
      Options::FOLD_OPEN_BAYS,
      "once the rooms are whole: a bay folds into the room it opens into widest",
      nullptr,
      [](const MergeInput& in, const PlanModel& model, AreaPlan* plan) {
        FoldOpenBays(in.graph, model, plan);
      },
      nullptr,
  });
  table.push_back({
      Options::FOLD_CORRIDOR_PIECES,
      "after the room joins: a small room that joined nothing and opens widely on two sides is "
      "a piece of a corridor",
      [](const Options& o) -> const Message* { return &o.corridor_pieces(); },
      [](const MergeInput& in, const PlanModel& model, AreaPlan* plan) {
        FoldCorridorPieces(in.graph, model, in.closed, in.options.corridor_pieces().below_m2(),
                           plan);
      },
      nullptr,
  });
  table.push_back({
      Options::JOIN_POROUS_BORDERS,
      "after the openings of rooms and corridors are settled: what still meets at many "
      "openings, one too narrow for a door, is one space",
      nullptr,
      [](const MergeInput& in, const PlanModel& model, AreaPlan* plan) {
        JoinAtPorousBorders(in.graph, model, in.closed,
                            in.map.robot_width_m() / in.grid.resolution_m(), plan);
      },
      nullptr,
  });
  table.push_back({
      Options::JOIN_SPLIT_CORRIDORS,
      "after the rooms are whole, so that a piece of a room is not taken for a piece of a "
      "corridor; it measures the plan again after every round of joins",
      nullptr,
      [](const MergeInput& in, const PlanModel&, AreaPlan* plan) {
        JoinSplitCorridors(in.graph, in.grid.resolution_m(), in.map.robot_width_m(), in.closed,
                           plan, {}, &in.grid);
      },
      nullptr,
  });
  table.push_back({
      Options::JOIN_CORRIDOR_STEMS,
      "last of the joins: a branch joins the corridor it opens from, whose width it is "
      "compared with, once that corridor is whole",
      nullptr,
      [](const MergeInput& in, const PlanModel& model, AreaPlan* plan) {
        JoinCorridorStems(in.graph, model, in.closed, plan);
      },
      nullptr,
  });
  table.push_back({
      Options::GROWTH_STOPS_AT_NARROW_GAPS,
      "after the joins, when the free space is split among the areas: it decides how far "
      "each area's cells grow (BuildAreaGraph reads its switch)",
      nullptr,
      nullptr,
      nullptr,
  });
  table.push_back({
      Options::KEEP_SMALL_CLOSED_ROOMS,
      "after the free space is split: it reads the areas' cells (their walls, their inner "
      "width) to keep a closet from being folded as a small area",
      [](const Options& o) -> const Message* { return &o.small_closed_rooms(); },
      nullptr,
      [](const MergeInput& in, const AreaPlan& plan, const AreaRaster& raster, int64_t min_cells) {
        return SmallClosedRooms(in.graph, plan, raster, in.grid, in.closed, min_cells,
                                in.options.small_closed_rooms().pocket_jamb_m());
      },
  });
  table.push_back({
      Options::OPEN_BORDER_PASSAGES,
      "once the areas are outlined: it puts passages on the borders they share and changes no "
      "area (AddAreasAndPassages reads its switch)",
      nullptr,
      nullptr,
      nullptr,
  });
  return table;
}

}  // namespace

const std::vector<MergePass>& MergePassTable() {
  static const std::vector<MergePass> table = MakeTable();
  return table;
}

std::string MergePassName(proto::MergeOptions::Pass pass) {
  return proto::MergeOptions::Pass_Name(pass);
}

void RunJoinPasses(const MergeInput& input, AreaPlan* plan) {
  for (const MergePass& row : MergePassTable()) {
    if (row.join == nullptr || !RunsStagePass(input.options, row.pass)) continue;
    row.join(input, MeasurePlan(input.graph, *plan, input.grid.resolution_m()), plan);
  }
}

std::vector<bool> KeptSmallAreas(const MergeInput& input, const AreaPlan& plan,
                                 const AreaRaster& raster, int64_t min_cells) {
  std::vector<bool> kept;
  for (const MergePass& row : MergePassTable()) {
    if (row.keep == nullptr || !RunsStagePass(input.options, row.pass)) continue;
    const std::vector<bool> more = row.keep(input, plan, raster, min_cells);
    kept.resize(std::max(kept.size(), more.size()), false);
    for (size_t k = 0; k < more.size(); ++k) kept[k] = kept[k] || more[k];
  }
  return kept;
}

}  // namespace areagraph
