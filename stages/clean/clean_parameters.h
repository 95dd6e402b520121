#pragma once

#include "proto/geometry.pb.h"
#include "proto/pipeline_options.pb.h"
#include "stages/clean/furniture_removal.h"

namespace areagraph {

// CleanOptions converted to pixels for one map.
struct CleanParameters {
  // k of CGAL's remove_outliers (which averages over the point itself and k
  // more).
  int outlier_neighbors = 18;
  // At most this percentage of the occupied cells is taken as outliers.
  double outlier_percent = 1.5;
  // Half the robot width: the radius of the furniture alpha shape's disk.
  double alpha_radius_px = 5;
  // Components with a shorter alpha-shape boundary are furniture.
  double furniture_max_perimeter_px = 80;
  // Unknown islands of at most this many cells become free.
  double unknown_island_max_cells = 0;
  // Furniture pieces' regions that are pieces of wall stay
  // (clean pass KEEP_WALL_PIECES).
  bool keep_wall_pieces = false;
  WallPieceSizes wall_pieces;
};

// Checks `options` (CheckCleanOptions), then what depends on the map: throws
// OptionsError for a robot width not smaller than the map, and InputError
// when the frame has no positive, finite resolution.
CleanParameters CleanParametersFor(const proto::CleanOptions& options,
                                   const proto::MapFrame& frame);

}  // namespace areagraph
