#pragma once

#include <functional>
#include <string>

#include "proto/artifacts.pb.h"
#include "proto/pipeline_options.pb.h"

namespace areagraph {

// ag-prune: the Topology Graph with a polygon on every edge (the paper's
// G_A^0). Voronoi vertices outside the boundary alpha shape or not on a free
// cell go, as do rays and edges closer to an obstacle than
// min_clearance_m; chains of degree-2 vertices become edges; short dead ends
// are removed with their polygons absorbed (Alg. 2); close junctions merge;
// the connected group with the most edge length stays, and so does every
// other group with at least prune.min_component_m2 of free space (each with
// the outline of the alpha-shape region around it in part_boundaries), and
// so does every group whose edges are at least prune.keep_groups_above_m long
// in total, beside a longer one in its part; the groups dropped are counted.
// Throws InputError ("no Topology Graph: ...") when nothing is left, and
// OptionsError on bad options. Calls
// `diagram_done`, when given, once it reads `diagram` no more (it copies the
// diagram's numbers first, before the boundary shape is built), so that a
// caller that owns the diagram can free it while the rest runs.
proto::TopologyGraph BuildTopologyGraph(const proto::VoronoiDiagram& diagram,
                                        const proto::CleanedMap& map,
                                        const proto::PruneOptions& options,
                                        const std::function<void()>& diagram_done = nullptr);

}  // namespace areagraph
