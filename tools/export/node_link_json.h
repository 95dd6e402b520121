#pragma once

#include <string>

#include "proto/artifacts.pb.h"

namespace areagraph {

// The Area Graph in networkx's node-link form, so that
// `networkx.node_link_graph(json.load(f))` gives an undirected MultiGraph
// that keeps parallel passages, keyed by the ids of ExportIds (the stable
// ids of a graph from ag-match, which a re-run keeps; else the indices):
// - directed false, multigraph true;
// - graph: name (the map), ids ("stable" or "index"), version (ag-match's
//   graphs), frame (its MapFrame), units ("metres");
// - nodes: id, stable_id (ag-match's graphs), index (in this version), name
//   (area_<id>), kind (room, corridor, dead_end), area_m2, centroid [x, y],
//   polygon (outer ring counter-clockwise, first point not repeated) and
//   holes (clockwise rings), all in world metres to the millimetre;
// - links: source and target (area ids), key and id (the passage's id),
//   stable_id and index (as for nodes), name (passage_<id>), width_m,
//   point [x, y] (where the graph edge crosses) and border (the line the
//   two areas share, or segment_m's two ends);
// - edges: the links again, since networkx >= 3.4 reads "edges" where
//   earlier versions (Debian 12 has 2.8) read "links".
// Throws InputError for coordinates that are not finite.
std::string AreaGraphToNodeLinkJson(const proto::AreaGraph& graph, const std::string& map_name);

}  // namespace areagraph
