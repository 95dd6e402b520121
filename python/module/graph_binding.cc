// areagraph._core.Graph: an Area Graph's areas, passages, networkx JSON and
// routes as plain Python values.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "python/module/bindings.h"
#include "python/module/graph_handle.h"
#include "tools/export/area_polygons.h"
#include "tools/export/node_link_json.h"

namespace areagraph::python {
namespace {

namespace py = pybind11;

py::tuple Xy(const proto::Point2& point) { return py::make_tuple(point.x(), point.y()); }
py::tuple Xy(const Vec2& point) { return py::make_tuple(point.x(), point.y()); }

// The stable id, or None in a graph without them (ag-merge's).
py::object StableId(const proto::AreaGraph& graph, int32_t stable_id) {
  if (!graph.has_version()) return py::none();
  return py::int_(stable_id);
}

py::list Points(const std::vector<proto::Point2>& points) {
  py::list list;
  for (const proto::Point2& point : points) list.append(Xy(point));
  return list;
}

// (id, stable id or None, kind, outer ring, holes, m², centroid) per area;
// rings as the JSON export writes them (outer counter-clockwise).
py::list Areas(const GraphHandle& handle) {
  const proto::AreaGraph& graph = handle.graph();
  py::list areas;
  for (const proto::Area& area : graph.areas()) {
    const proto::Polygon polygon = AreaPolygonMetres(graph, area);
    py::list holes;
    for (const proto::Ring& hole : polygon.holes()) holes.append(Points(OrientedRing(hole, false)));
    areas.append(py::make_tuple(
        area.id(), StableId(graph, area.stable_id()), AreaKindName(area.kind()),
        Points(OrientedRing(polygon.outer(), true)), holes, area.area_m2(), Xy(area.centroid_m())));
  }
  return areas;
}

// (id, stable id or None, area index a, area index b, border, width, point)
// per passage.
py::list Passages(const GraphHandle& handle) {
  const proto::AreaGraph& graph = handle.graph();
  py::list passages;
  for (const proto::Passage& passage : graph.passages()) {
    passages.append(py::make_tuple(passage.id(), StableId(graph, passage.stable_id()),
                                   passage.area_a(), passage.area_b(), Points(PassageLine(passage)),
                                   passage.width_m(), Xy(passage.point_m())));
  }
  return passages;
}

// None, or (length, area indices, passage indices, polyline).
py::object FindRoute(GraphHandle& handle, double start_x, double start_y, double goal_x,
                     double goal_y) {
  const RouteAnswer answer =
      handle.router().FindRoute(Vec2(start_x, start_y), Vec2(goal_x, goal_y));
  if (!answer.route) return py::none();
  py::list polyline;
  for (const Vec2& point : answer.route->polyline) polyline.append(Xy(point));
  return py::make_tuple(answer.route->length_m, py::cast(answer.route->areas),
                        py::cast(answer.route->passages), polyline);
}

}  // namespace

void AddGraph(py::module_& module) {
  py::class_<GraphHandle, std::shared_ptr<GraphHandle>>(module, "Graph",
                                                        "An Area Graph held in C++.")
      .def_property_readonly("map_name", &GraphHandle::map_name)
      .def_property_readonly("has_stable_ids",
                             [](const GraphHandle& handle) { return handle.graph().has_version(); })
      .def_property_readonly("version",
                             [](const GraphHandle& handle) -> py::object {
                               if (!handle.graph().has_version()) return py::none();
                               return py::int_(handle.graph().version().number());
                             })
      .def("serialized",
           [](const GraphHandle& handle) { return py::bytes(handle.graph().SerializeAsString()); })
      .def("areas", &Areas)
      .def("passages", &Passages)
      .def("node_link_json",
           [](const GraphHandle& handle) {
             return AreaGraphToNodeLinkJson(handle.graph(), handle.map_name());
           })
      .def("area_at", [](GraphHandle& handle, double x,
                         double y) { return handle.free_space().AreaAt(Vec2(x, y)); })
      .def("route", &FindRoute)
      .def("router_size", [](GraphHandle& handle) {
        return py::make_tuple(handle.router().corner_count(), handle.router().link_count());
      });
}

}  // namespace areagraph::python
