#include "tools/route/route_report.h"

#include <cstdio>

namespace areagraph {
namespace {

void SetPoint(const Vec2& point, proto::Point2* out) {
  out->set_x(point.x());
  out->set_y(point.y());
}

// Millimetres are as fine as a map of 5 cm cells can tell.
std::string Metres(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.3f", value);
  return text;
}

std::string PointText(const proto::Point2& point) {
  return "(" + Metres(point.x()) + ", " + Metres(point.y()) + ")";
}

template <typename Ids>
std::string IdList(const Ids& ids) {
  std::string text;
  for (const int id : ids) text += " " + std::to_string(id);
  return text.empty() ? " none" : text;
}

}  // namespace

route::RouteReport ReportRoute(const proto::AreaGraph& graph, const std::string& map_name,
                               const Vec2& start, const Vec2& goal, const Route& route) {
  const bool stable = graph.has_version();
  route::RouteReport report;
  report.set_map_name(map_name);
  SetPoint(start, report.mutable_start());
  SetPoint(goal, report.mutable_goal());
  report.set_length_m(route.length_m);
  for (const int area : route.areas) {
    report.add_areas(stable ? graph.areas(area).stable_id() : graph.areas(area).id());
  }
  for (const int passage : route.passages) {
    report.add_passages(stable ? graph.passages(passage).stable_id()
                               : graph.passages(passage).id());
  }
  for (const Vec2& point : route.polyline) SetPoint(point, report.add_polyline());
  return report;
}

std::string RouteText(const route::RouteReport& report) {
  std::string polyline;
  for (const proto::Point2& point : report.polyline()) polyline += " " + PointText(point);
  return "map '" + report.map_name() + "': route from " + PointText(report.start()) + " to " +
         PointText(report.goal()) + ": " + Metres(report.length_m()) +
         " m\nareas:" + IdList(report.areas()) + "\npassages:" + IdList(report.passages()) +
         "\npolyline:" + polyline + "\n";
}

}  // namespace areagraph
