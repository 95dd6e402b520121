#pragma once

#include <Eigen/Core>
#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/geometry/site_triangulation.h"

namespace areagraph {

// Options of the diagram itself (the stage's options map onto these).
struct VoronoiBuildOptions {
  // Keep the unbounded edges (rays) of the diagram's outer faces.
  bool keep_rays = true;
};

// The Voronoi diagram of `sites` (pixel coordinates), as the dual of their
// Delaunay triangulation. Fills the site, vertex and edge arrays of the result
// (format 2, stages/common/voronoi_arrays.h); the caller sets format_version
// and frame.
//
// - Vertices are circumcentres of finite Delaunay faces. Faces whose
//   circumcircles coincide (co-circular sites, everywhere on a pixel grid)
//   become ONE vertex, so the zero-length edges between them never appear.
//   The graph stays connected because only such edges are dropped.
// - Each Delaunay edge between two different vertices gives one segment; a
//   convex-hull edge gives a ray (target -1) leaving its finite face's vertex.
// - left_site/right_site: walking from source to target (or along the ray),
//   left_site is on the left in pixel coordinates with y down, that is
//   cross(target - source, left - source) < 0 with cross(u, v) = u.x*v.y - u.y*v.x.
//   This is exact: it comes from the triangulation's orientation, not from
//   rounding-prone coordinates.
// - An edge's clearance is its smallest distance to its two sites.
// Fewer than three sites, or sites all on one line, give no vertices and no
// edges.
proto::VoronoiDiagram BuildVoronoiDiagram(const std::vector<Eigen::Vector2d>& sites,
                                          const VoronoiBuildOptions& options = {});
// The same, also giving the Delaunay triangulation it is the dual of (the
// stage keeps it for prune, KeepSiteTriangulation); null leaves it freed.
proto::VoronoiDiagram BuildVoronoiDiagram(const std::vector<Eigen::Vector2d>& sites,
                                          const VoronoiBuildOptions& options,
                                          SiteTriangulationPtr* triangulation_out);

}  // namespace areagraph
