#pragma once

#include "proto/artifacts.pb.h"
#include "tools/export/viewer_page.pb.h"

namespace areagraph {

// Sets run.route_graph to the routes' graph of `graph` (see RouteGraph in
// viewer_page.proto), or clears it when the graph cannot route (no polygons
// in metres, no map frame): the page then says so instead of routing.
void SetRouteGraph(const proto::AreaGraph& graph, viewer::Run* run);

}  // namespace areagraph
