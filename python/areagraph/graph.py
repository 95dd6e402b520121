"""The Area Graph of one map: areas, passages, networkx, and routes between points."""

import json

from . import _messages


class Area:
    """One area of an Area Graph: a room, a corridor or a dead end.

    id: its index in the graph (AreaGraph.areas[id] is this area).
    stable_id: the id it keeps across the map's versions (ag-match); None in a graph without
        stable ids (ag-merge's, read from a store after ag-merge alone).
    kind: "room", "corridor" or "dead_end".
    polygon: a shapely Polygon with holes, in metres (map frame); the areas tile the free
        space and neighbours share their border vertex for vertex.
    area_m2: its area in square metres.
    centroid: (x, y) in metres.
    """

    __slots__ = ("id", "stable_id", "kind", "polygon", "area_m2", "centroid")

    def __init__(self, id, stable_id, kind, polygon, area_m2, centroid):
        self.id = id
        self.stable_id = stable_id
        self.kind = kind
        self.polygon = polygon
        self.area_m2 = area_m2
        self.centroid = centroid

    def __repr__(self):
        return "Area(stable_id=%s, kind=%r, area_m2=%.2f)" % (self.stable_id, self.kind,
                                                             self.area_m2)


class Passage:
    """One passage (a door or an opening) between two areas.

    id: its index in the graph.
    stable_id: the id it keeps across the map's versions; None without stable ids.
    areas: the two areas it joins, by stable id (by id in a graph without stable ids).
    border: a shapely LineString, the piece of border the two areas share there (metres).
    width_m: the free width of the opening between the obstacles on either side.
    point: (x, y) where the graph edge crosses the opening.
    """

    __slots__ = ("id", "stable_id", "areas", "border", "width_m", "point")

    def __init__(self, id, stable_id, areas, border, width_m, point):
        self.id = id
        self.stable_id = stable_id
        self.areas = areas
        self.border = border
        self.width_m = width_m
        self.point = point

    def __repr__(self):
        return "Passage(stable_id=%s, areas=%s, width_m=%.2f)" % (self.stable_id, self.areas,
                                                                 self.width_m)


class Route:
    """A route through the free space of an Area Graph (AreaGraph.route).

    length_m: its length in metres.
    areas: the areas it runs through, in order, by stable id (by id without stable ids).
    passages: the passages it crosses, in order, the same way.
    polyline: a list of (x, y) in metres from the start to the goal; it stays inside the
        areas and crosses from one area to the next only through passages.
    """

    __slots__ = ("length_m", "areas", "passages", "polyline")

    def __init__(self, length_m, areas, passages, polyline):
        self.length_m = length_m
        self.areas = areas
        self.passages = passages
        self.polyline = polyline

    @property
    def linestring(self):
        """The polyline as a shapely LineString."""
        from shapely.geometry import LineString
        return LineString(self.polyline)

    def __repr__(self):
        return "Route(length_m=%.3f, areas=%s, passages=%s)" % (self.length_m, self.areas,
                                                               self.passages)


class AreaGraph:
    """The Area Graph of one map: what areagraph.segment() and Store.area_graph() return.

    name: the map's name. version: its number in the map's history (None without stable ids).
    areas: list of Area, indexed by Area.id. passages: list of Passage, indexed by Passage.id.
    Ids: a graph made by ag-match (segment() always is) gives every area and passage a
    stable_id, and the areas of passages and routes are given by stable id; a graph straight
    from ag-merge has none, and ids stand in for them.
    """

    def __init__(self, handle):
        self._handle = handle
        self._areas = None
        self._passages = None

    @property
    def name(self):
        """The map's name."""
        return self._handle.map_name

    @property
    def version(self):
        """The graph's number in its map's history of versions, or None (ag-merge's)."""
        return self._handle.version

    @property
    def areas(self):
        """The areas (list of Area), indexed by Area.id."""
        if self._areas is None:
            from shapely.geometry import Polygon
            self._areas = [
                Area(id, stable_id, kind, Polygon(outer, holes), area_m2, centroid)
                for id, stable_id, kind, outer, holes, area_m2, centroid in self._handle.areas()
            ]
        return self._areas

    @property
    def passages(self):
        """The passages (list of Passage), indexed by Passage.id."""
        if self._passages is None:
            from shapely.geometry import LineString
            keys = self._area_keys()
            self._passages = [
                Passage(id, stable_id, (keys[a], keys[b]), LineString(border), width_m, point)
                for id, stable_id, a, b, border, width_m, point in self._handle.passages()
            ]
        return self._passages

    @property
    def message(self):
        """The graph as its protobuf message (areagraph.proto.AreaGraph, proto/artifacts.proto)."""
        return _messages.parse("areagraph.proto.AreaGraph", self._handle.serialized())

    def to_networkx(self):
        """The graph as ag-export --format json gives it to networkx: an undirected MultiGraph
        with a node per area (keyed by Area.id; attributes stable_id, name, kind, area_m2,
        centroid, polygon, holes) and an edge per passage (keyed by Passage.id; attributes id,
        stable_id, name, width_m, point, border), and the map's name and frame in .graph."""
        import networkx
        return networkx.node_link_graph(json.loads(self._handle.node_link_json()))

    def area_at(self, x, y):
        """The Area whose polygon holds the point (x, y) in metres (its border included), or
        None."""
        index = self._handle.area_at(float(x), float(y))
        return self.areas[index] if index >= 0 else None

    def route(self, start_xy, goal_xy):
        """The shortest route from start_xy to goal_xy, both (x, y) in metres, as a Route; None
        when the goal cannot be reached from the start.

        The route is made of straight lines through the areas that bend only at corners of the
        free space, and it crosses a passage anywhere along its border. A point outside every
        area starts from (or ends at) the nearest point of an area within 1 m; farther away
        there is no route. The first call builds the graph of corners (about a second on a
        large floor); later calls take about a millisecond.
        """
        (start_x, start_y), (goal_x, goal_y) = start_xy, goal_xy
        found = self._handle.route(float(start_x), float(start_y), float(goal_x), float(goal_y))
        if found is None:
            return None
        length_m, areas, passages, polyline = found
        area_keys = self._area_keys()
        passage_keys = [p.stable_id if p.stable_id is not None else p.id for p in self.passages]
        return Route(length_m, [area_keys[a] for a in areas], [passage_keys[p] for p in passages],
                     polyline)

    def _area_keys(self):
        """Each area's stable id, or its id in a graph without stable ids."""
        return [a.stable_id if a.stable_id is not None else a.id for a in self.areas]

    def __repr__(self):
        return "AreaGraph(name=%r, areas=%d, passages=%d)" % (self.name, len(self.areas),
                                                             len(self.passages))
