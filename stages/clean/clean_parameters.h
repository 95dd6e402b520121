#pragma once

#include "proto/geometry.pb.h"
#include "proto/pipeline_options.pb.h"

namespace areagraph {

// CleanOptions checked against one map and converted to pixels.
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
};

// Throws OptionsError (one line naming the option) for values that are not
// finite or make no sense: outlier_neighbors outside [2, 1000] (k = 1 would
// see only the point itself), outlier_percent outside [0, 100), a robot width
// that is not positive or wider than the map, a negative perimeter. Throws
// InputError when the frame has no positive, finite resolution.
CleanParameters CheckCleanOptions(const proto::CleanOptions& options, const proto::MapFrame& frame);

}  // namespace areagraph
