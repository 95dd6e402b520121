"""AreaGraph.route(): routes stay in the areas, change areas only through passages, are no longer
than needed, and agree with ag-route; on the examples and, when ../shared/data is there, on
lab_a."""

import json
import math
import os
import random
import unittest

from shapely.geometry import LineString, Point
from shapely.ops import unary_union

import areagraph
from python_test_support import TempDirTest, example, run_tool, shared_map

OFFICE = example("office_small.png")


def points_inside(graph, count, seed):
    """`count` random points inside the graph's areas (uniform over the union)."""
    rng = random.Random(seed)
    union = unary_union([area.polygon for area in graph.areas])
    min_x, min_y, max_x, max_y = union.bounds
    points = []
    while len(points) < count:
        x, y = rng.uniform(min_x, max_x), rng.uniform(min_y, max_y)
        if union.contains(Point(x, y)):
            points.append((x, y))
    return points


class RouteChecks:
    """Checks every route of a graph must pass."""

    def check_route(self, graph, route, start, goal, union):
        self.assertEqual(route.polyline[0], tuple(start))
        self.assertEqual(route.polyline[-1], tuple(goal))
        line = LineString(route.polyline)
        self.assertAlmostEqual(line.length, route.length_m, places=9)
        self.assertGreaterEqual(route.length_m, math.dist(start, goal) - 1e-9)
        self.assertTrue(union.buffer(1e-6).covers(line), "the route leaves the areas")
        self.check_area_changes(graph, route)

    def check_area_changes(self, graph, route):
        """Walks the polyline in 1 cm steps: wherever it leaves the areas it was in, a passage
        between the area it leaves and one it enters must be within 2 cm, and the route must
        list that step. Points on a border are in every area that holds them."""
        from shapely.prepared import prep
        closed = [(a, prep(a.polygon.buffer(1e-6)), a.polygon.bounds) for a in graph.areas]
        passages = {}
        for passage in graph.passages:
            passages.setdefault(frozenset(passage.areas), []).append(passage)
        steps = set(zip(route.areas, route.areas[1:]))
        current = None
        for (x0, y0), (x1, y1) in zip(route.polyline, route.polyline[1:]):
            count = max(1, int(math.dist((x0, y0), (x1, y1)) / 0.01))
            for i in range(count + 1):
                x, y = x0 + (x1 - x0) * i / count, y0 + (y1 - y0) * i / count
                point = Point(x, y)
                holding = [a.stable_id for a, covers, (min_x, min_y, max_x, max_y) in closed
                           if min_x - 1e-6 <= x <= max_x + 1e-6 and
                           min_y - 1e-6 <= y <= max_y + 1e-6 and covers.covers(point)]
                if not holding:
                    continue  # a snapped end's way in
                if current is None:
                    current = route.areas[0] if route.areas[0] in holding else holding[0]
                if current in holding:
                    continue
                entered = [b for b in holding for p in passages.get(frozenset((current, b)), [])
                           if p.border.distance(point) < 0.02]
                self.assertTrue(entered, "from area %d to %s away from a passage at %s" %
                                (current, holding, point))
                self.assertIn((current, entered[0]), steps)
                current = entered[0]
        self.assertEqual(len(route.passages), len(route.areas) - 1)
        self.assertEqual(current, route.areas[-1])


class ExampleRouteTest(TempDirTest, RouteChecks):

    def test_routes_between_every_pair_of_areas(self):
        graph = areagraph.segment(OFFICE)
        union = unary_union([area.polygon for area in graph.areas])
        starts = [a.polygon.representative_point() for a in graph.areas]
        for i, a in enumerate(starts):
            for b in starts[i + 1:]:
                route = graph.route((a.x, a.y), (b.x, b.y))
                self.assertIsNotNone(route)
                self.check_route(graph, route, (a.x, a.y), (b.x, b.y), union)
                back = graph.route((b.x, b.y), (a.x, a.y))
                self.assertAlmostEqual(back.length_m, route.length_m, places=6)

    def test_an_end_near_an_area_snaps_and_a_far_one_has_no_route(self):
        graph = areagraph.segment(OFFICE)
        area = max(graph.areas, key=lambda a: a.area_m2)
        min_x, min_y, max_x, max_y = graph.areas[0].polygon.bounds
        inside = area.polygon.representative_point()
        outside = min(
            (p for p in ((min_x - 0.5, min_y - 0.5), (max_x + 0.5, max_y + 0.5))),
            key=lambda p: area.polygon.distance(Point(p)))
        union = unary_union([a.polygon for a in graph.areas])
        distance = union.distance(Point(outside))
        route = graph.route((inside.x, inside.y), outside)
        if distance <= 1:
            self.assertIsNotNone(route)
            self.assertEqual(route.polyline[-1], outside)
            self.assertAlmostEqual(math.dist(route.polyline[-2], outside), distance, places=6)
        self.assertIsNone(graph.route((inside.x, inside.y), (1e4, 1e4)))

    def test_agrees_with_ag_route(self):
        store = os.path.join(self.dir, "routes.db")
        run_tool("ag-run", "--store", store, "--jobs", "1", OFFICE)
        graph = areagraph.Store(store).area_graph("office_small")
        start, goal = points_inside(graph, 2, seed=3)
        route = graph.route(start, goal)
        report = json.loads(run_tool(
            "ag-route", "--store", store, "--map", "office_small", "--from", "%r,%r" % start,
            "--to", "%r,%r" % goal, "--json").stdout)
        self.assertAlmostEqual(report["length_m"], route.length_m, places=9)
        self.assertEqual(report.get("areas", []), route.areas)
        self.assertEqual(report.get("passages", []), route.passages)


class RealMapRouteTest(unittest.TestCase, RouteChecks):

    def check_map(self, name):
        graph = areagraph.segment(shared_map("areagraph/input/%s.png" % name))
        union = unary_union([area.polygon for area in graph.areas])
        points = points_inside(graph, 120, seed=42)
        found = 0
        for start, goal in zip(points[0::2], points[1::2]):
            route = graph.route(start, goal)
            if route is None:
                continue  # different parts of the map
            found += 1
            self.check_route(graph, route, start, goal, union)
        self.assertGreaterEqual(found, 30)

    def test_lab_a_routes_stay_in_free_space(self):
        self.check_map("lab_a")

    def test_lab_e_routes_stay_in_free_space(self):
        self.check_map("lab_e")


if __name__ == "__main__":
    unittest.main()
