#pragma once

#include <map>
#include <memory>
#include <vector>

#include "proto/artifacts.pb.h"
#include "stages/geometry/cell_grid.h"
#include "stages/geometry/ring_points.h"
#include "stages/geometry/site_alpha_shape.h"
#include "stages/prune/chain_graph.h"

namespace areagraph {

// The numbers of a Voronoi diagram, copied out of its messages (about three
// times their size in memory), so that the diagram can go before the
// boundary shape is built: on a big map the two would be most of the peak.
struct PlainVoronoi {
  struct Edge {
    Edge() {}  // left unset: the copy below fills every entry, over ranges
    int source;
    int target;
    int left_site;
    int right_site;
    double clearance_px;
  };
  PointList sites;
  PointList positions;
  std::vector<double> clearances;
  std::vector<Edge> edges;

  // `diagram` holds arrays of matching lengths (PackedVoronoi), read here
  // through their data pointers (millions of entries on a big map), over
  // ranges in parallel: the sized arrays are not written until then, so
  // their fresh pages are touched in the ranges too.
  explicit PlainVoronoi(const proto::VoronoiDiagram& diagram);
};

// The numbers of a diagram of either format (a format-1 one is converted
// first and the conversion dropped).
PlainVoronoi PlainVoronoiOf(const proto::VoronoiDiagram& diagram);

// The Voronoi edges that survive the boundary, free-cell and clearance
// filters, joined into chains through degree-2 vertices
// (ChainGraph::JoinDegreeTwoChains), the enclosed region of each chain vertex,
// and the outline of every region that holds one.
struct FilteredGraph {
  ChainGraph graph;
  std::vector<int> vertex_region;  // by chain vertex
  std::map<int, proto::Polygon> region_outlines;
};

// Builds the FilteredGraph. Frees `boundary_shape` (its triangulation is
// about as big as the diagram) once the outlines are taken, before the
// chains are built.
FilteredGraph FilteredVoronoiGraph(const PlainVoronoi& diagram, const CellGrid& grid,
                                   std::unique_ptr<SiteAlphaShape> boundary_shape,
                                   double min_clearance_px);

}  // namespace areagraph
