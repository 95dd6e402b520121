#pragma once

#include "proto/artifacts.pb.h"

namespace areagraph {

// Reading a VoronoiDiagram artifact of either format: format 2 (voronoi 3)
// holds parallel packed arrays, format 1 (stores written before) a message
// per site, vertex and edge. Readers index the arrays of the diagram that
// PackedVoronoi returns.

// Whether `diagram` holds format 1's messages rather than arrays.
bool HasVoronoiMessages(const proto::VoronoiDiagram& diagram);

// `diagram` itself when it holds arrays; a format-1 diagram is converted into
// `*converted`, which is returned. Throws InputError when arrays that belong
// together differ in length (a corrupt artifact); indices are the caller's
// to check.
const proto::VoronoiDiagram& PackedVoronoi(const proto::VoronoiDiagram& diagram,
                                           proto::VoronoiDiagram* converted);

// Counts of a diagram of either format (summaries of stored artifacts).
inline int VoronoiSiteCount(const proto::VoronoiDiagram& d) {
  return HasVoronoiMessages(d) ? d.sites_size() : d.site_x_size();
}
inline int VoronoiVertexCount(const proto::VoronoiDiagram& d) {
  return HasVoronoiMessages(d) ? d.vertices_size() : d.vertex_x_size();
}
inline int VoronoiEdgeCount(const proto::VoronoiDiagram& d) {
  return HasVoronoiMessages(d) ? d.edges_size() : d.edge_source_size();
}

}  // namespace areagraph
