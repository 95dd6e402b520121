#pragma once

#include <google/protobuf/message.h>

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "proto/artifacts.pb.h"
#include "proto/pipeline_options.pb.h"
#include "stages/geometry/cell_grid.h"
#include "stages/merge/area_assignment.h"
#include "stages/merge/area_raster.h"
#include "stages/merge/plan_model.h"

namespace areagraph {

// What every merge pass reads besides the plan it changes.
struct MergeInput {
  const proto::CutGraph& graph;
  const proto::CleanedMap& map;
  const CellGrid& grid;
  const proto::MergeOptions& options;
  // Per graph vertex: a cut that ag-cut made on a door or wall gap it closed
  // on purpose (PassagePoint.closed_by_cut), where no pass joins the areas
  // (ClosedVertices).
  // Set once, here, for every pass.
  std::vector<bool> closed;
  // The cells of furniture rows (FurnitureRowCells) where JOIN_FURNITURE_ROWS
  // runs and finds any, else empty: that pass and the areas' kinds read them.
  cv::Mat furniture_rows;
};

// One row of the merge's pass table: a rule beyond the paper that changes
// which edges make up an area, or (join and keep both null) one whose switch
// is read where the free space is split (GROWTH_STOPS_AT_NARROW_GAPS) or the
// passages are found (OPEN_BORDER_PASSAGES).
struct MergePass {
  proto::MergeOptions::Pass pass;
  // Why it runs where it does.
  const char* order;
  // Its options within MergeOptions, or null for a pass without any.
  const google::protobuf::Message* (*options_of)(const proto::MergeOptions& options);
  // A pass on the plan, before the free space is split among the areas:
  // joins areas. The model is measured on the plan as it stands.
  void (*join)(const MergeInput& input, const PlanModel& model, AreaPlan* plan);
  // A pass on the split free space: marks the areas under merge.min_area_m2
  // (`min_cells`) that FoldSmallAreas keeps. Null for a join pass.
  std::vector<bool> (*keep)(const MergeInput& input, const AreaPlan& plan, const AreaRaster& raster,
                            int64_t min_cells);
};

// Every pass, in the order they run. Nothing else lists them: the option
// merge.skip_passes names them, tools/bench-ablation.sh turns each off in
// turn, and examples/options/paper.pbtxt skips them all.
const std::vector<MergePass>& MergePassTable();

// A pass's name as merge.skip_passes spells it, e.g. "JOIN_CORRIDOR_PIECES".
std::string MergePassName(proto::MergeOptions::Pass pass);

// The join passes that the options run, in order, each on a model of the
// plan as the passes before it left it.
void RunJoinPasses(const MergeInput& input, AreaPlan* plan);

// The areas that FoldSmallAreas keeps however small, by the keep passes
// that the options run (empty when none runs).
std::vector<bool> KeptSmallAreas(const MergeInput& input, const AreaPlan& plan,
                                 const AreaRaster& raster, int64_t min_cells);

}  // namespace areagraph
