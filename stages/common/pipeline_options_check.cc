#include "stages/common/pipeline_options_check.h"

#include <cmath>

#include "common/error.h"
#include "common/text.h"

namespace areagraph {
namespace {

void Require(bool ok, const std::string& message) {
  if (!ok) throw OptionsError(message);
}

// A length or area option that may be zero: finite and not negative.
void RequireNotNegative(double value, const std::string& key, const char* unit) {
  Require(std::isfinite(value) && value >= 0,
          key + " must be zero or more " + unit + ", got " + FormatNumber(value));
}

void RequirePositive(double value, const std::string& key, const char* unit) {
  Require(std::isfinite(value) && value > 0,
          key + " must be a positive number of " + unit + ", got " + FormatNumber(value));
}

}  // namespace

void CheckResolution(double resolution_m, const std::string& what, bool is_option) {
  if (resolution_m >= kMinResolutionM && resolution_m <= kMaxResolutionM) return;  // NaN fails
  const std::string message = what + " must be a resolution in [" + FormatNumber(kMinResolutionM) +
                              ", " + FormatNumber(kMaxResolutionM) + "] metres per pixel, got " +
                              FormatNumber(resolution_m);
  if (is_option) throw OptionsError(message);
  throw InputError(message);
}

void CheckImportOptions(const proto::ImportOptions& options) {
  CheckResolution(options.resolution_m(), "import.resolution_m", /*is_option=*/true);
  Require(options.max_pixels() > 0,
          "import.max_pixels must be positive, got " + std::to_string(options.max_pixels()));
  const int occupied_max = options.occupied_max_grey();
  const int free_min = options.free_min_grey();
  Require(occupied_max >= 0 && free_min <= 255 && occupied_max < free_min,
          "import.occupied_max_grey (" + std::to_string(occupied_max) +
              ") and import.free_min_grey (" + std::to_string(free_min) +
              ") must satisfy 0 <= occupied_max_grey < free_min_grey <= 255");
}

void CheckCleanOptions(const proto::CleanOptions& options) {
  // k = 1 would see only the point itself.
  Require(options.outlier_neighbors() >= 2 && options.outlier_neighbors() <= 1000,
          "clean.outlier_neighbors must be between 2 and 1000 (got " +
              std::to_string(options.outlier_neighbors()) + ")");
  const double percent = options.outlier_percent();
  Require(
      std::isfinite(percent) && percent >= 0 && percent < 100,
      "clean.outlier_percent must be at least 0 and below 100 (got " + FormatNumber(percent) + ")");
  Require(std::isfinite(options.robot_width_m()) && options.robot_width_m() > 0,
          "clean.robot_width_m must be a positive number of metres (got " +
              FormatNumber(options.robot_width_m()) + ")");
  Require(std::isfinite(options.furniture_max_perimeter_m()) &&
              options.furniture_max_perimeter_m() >= 0,
          "clean.furniture_max_perimeter_m must be a number of metres >= 0 (got " +
              FormatNumber(options.furniture_max_perimeter_m()) + ")");
  Require(std::isfinite(options.unknown_island_max_m2()) && options.unknown_island_max_m2() >= 0,
          "clean.unknown_island_max_m2 must be a number of square metres >= 0 (got " +
              FormatNumber(options.unknown_island_max_m2()) + ")");
}

void CheckPruneOptions(const proto::PruneOptions& options) {
  RequirePositive(options.boundary_alpha_radius_m(), "prune.boundary_alpha_radius_m", "metres");
  RequireNotNegative(options.min_clearance_m(), "prune.min_clearance_m", "metres");
  RequireNotNegative(options.dead_end_max_length_m(), "prune.dead_end_max_length_m", "metres");
  Require(options.dead_end_passes() >= 0 && options.dead_end_passes() <= 1000,
          "prune.dead_end_passes must be between 0 and 1000, got " +
              std::to_string(options.dead_end_passes()));
  RequireNotNegative(options.min_component_m2(), "prune.min_component_m2", "square metres");
  RequireNotNegative(options.keep_groups_above_m(), "prune.keep_groups_above_m", "metres");
}

void CheckCutOptions(const proto::CutOptions& options) {
  const double door = options.door_width_m();
  const double corridor = options.corridor_width_m();
  // 0 means "not given", as in the stored canonical options.
  Require(std::isfinite(door) && door >= 0,
          "cut.door_width_m must be a positive number of metres, got " + FormatNumber(door));
  Require(
      std::isfinite(corridor) && corridor >= 0,
      "cut.corridor_width_m must be a positive number of metres, got " + FormatNumber(corridor));
  Require((door > 0) == (corridor > 0),
          "cut.door_width_m and cut.corridor_width_m work together: set both or neither");
  // The paper's strategy: W = door + 0.1 m or corridor - 0.1 m.
  Require(!(door > 0) || door < corridor || corridor - 0.1 > 0,
          "cut.corridor_width_m = " + FormatNumber(corridor) +
              " m gives no room width (W = corridor - 0.1 m)");
  // 0: W is estimated from the map.
  RequireNotNegative(options.room_width_m(), "cut.room_width_m", "metres");
  RequireNotNegative(options.islands().max_length_m(), "cut.islands.max_length_m", "metres");
  RequireNotNegative(options.wall_gaps().max_width_m(), "cut.wall_gaps.max_width_m", "metres");
  RequireNotNegative(options.mouths().max_width_m(), "cut.mouths.max_width_m", "metres");
  const double share = options.islands().end_on_face_share();
  Require(std::isfinite(share) && share >= 0 && share <= 1,
          "cut.islands.end_on_face_share must be between 0 and 1, got " + FormatNumber(share));
}

void CheckMergeOptions(const proto::MergeOptions& options) {
  RequireNotNegative(options.min_area_m2(), "merge.min_area_m2", "square metres");
  RequireNotNegative(options.outline_tolerance_m(), "merge.outline_tolerance_m", "metres");
  RequireNotNegative(options.min_hole_m2(), "merge.min_hole_m2", "square metres");
  RequireNotNegative(options.corridor_pieces().below_m2(), "merge.corridor_pieces.below_m2",
                     "square metres");
  RequireNotNegative(options.small_closed_rooms().pocket_jamb_m(),
                     "merge.small_closed_rooms.pocket_jamb_m", "metres");
  const double elongation = options.furniture_gaps().max_elongation();
  Require(elongation == 0 || (std::isfinite(elongation) && elongation >= 1),
          "merge.furniture_gaps.max_elongation must be 0 (any shape) or at least 1, got " +
              FormatNumber(elongation));
}

void CheckMatchOptions(const proto::MatchOptions& options) {
  Require(options.min_overlap() > 0 && options.min_overlap() <= 1,
          "match.min_overlap = " + FormatNumber(options.min_overlap()) +
              " must be above 0 and at most 1 (a fraction of the smaller area)");
  RequireNotNegative(options.passage_max_shift_m(), "match.passage_max_shift_m", "metres");
  RequireNotNegative(options.fold_fragments_below_m2(), "match.fold_fragments_below_m2",
                     "square metres");
  RequireNotNegative(options.split_joins_below_m2(), "match.split_joins_below_m2", "square metres");
  RequireNotNegative(options.split_joins_wall_margin_m(), "match.split_joins_wall_margin_m",
                     "metres");
}

void CheckPipelineOptions(const proto::PipelineOptions& options) {
  CheckImportOptions(options.import());
  CheckCleanOptions(options.clean());
  CheckPruneOptions(options.prune());
  CheckCutOptions(options.cut());
  CheckMergeOptions(options.merge());
  CheckMatchOptions(options.match());
}

void CheckOutlineTolerance(const proto::MergeOptions& options, double room_width_m) {
  if (!(room_width_m > 0) || options.outline_tolerance_m() < room_width_m / 2) return;
  throw OptionsError("merge.outline_tolerance_m = " + FormatNumber(options.outline_tolerance_m()) +
                     " m is not below half the room width W = " + FormatNumber(room_width_m) +
                     " m of this map: outlines would stray across rooms");
}

}  // namespace areagraph
