#pragma once

#include <string>

#include "proto/artifacts.pb.h"
#include "tools/route/area_router.h"
#include "tools/route/route_report.pb.h"

namespace areagraph {

// `route` on `graph` from `start` to `goal`, with ids as the graph gives
// them (stable ids when it has them).
route::RouteReport ReportRoute(const proto::AreaGraph& graph, const std::string& map_name,
                               const Vec2& start, const Vec2& goal, const Route& route);

// The report as lines of text: the length, the areas, the passages and the
// polyline.
std::string RouteText(const route::RouteReport& report);

}  // namespace areagraph
