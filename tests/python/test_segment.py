"""areagraph.segment(): the same Area Graph as ag-run, from a file or an array, and the tools'
error messages as exceptions."""

import json
import os
import unittest

import networkx
import numpy

import areagraph
from python_test_support import TempDirTest, example, exported_json, run_tool, tool_error

OFFICE = example("office_small.png")


def node_link(graph):
    """The graph as node-link data, for comparing two graphs exactly."""
    return networkx.node_link_data(graph.to_networkx())


def ros_grid(grid_map):
    """A GridMap message as a ROS OccupancyGrid array: row 0 at the bottom, 0 free, 100
    occupied, 255 unknown."""
    frame = grid_map.frame
    cells = numpy.frombuffer(grid_map.cells, dtype=numpy.uint8).reshape(frame.height_px,
                                                                        frame.width_px)
    return numpy.choose(cells, [0, 100, 255]).astype(numpy.uint8)[::-1]


class SegmentTest(TempDirTest):

    def ag_run(self, *sets):
        store = os.path.join(self.dir, "runs.db")
        arguments = ["--store", store, "--jobs", "1"]
        for assignment in sets:
            arguments += ["--set", assignment]
        run_tool("ag-run", *arguments, OFFICE)
        return store

    def test_a_map_file_gives_ag_runs_graph(self):
        graph = areagraph.segment(OFFICE)
        expected = exported_json(self.ag_run(), "office_small")
        self.assertEqual(json.loads(graph._handle.node_link_json()), expected)
        self.assertEqual(node_link(graph),
                         networkx.node_link_data(networkx.node_link_graph(expected)))
        self.assertEqual(graph.name, "office_small")
        self.assertEqual(graph.version, 1)
        self.assertGreaterEqual(len(graph.areas), 3)
        self.assertEqual([area.id for area in graph.areas], list(range(len(graph.areas))))
        self.assertEqual(len(graph.passages), len(expected["links"]))

    def test_overrides_act_as_ag_run_set(self):
        expected = exported_json(self.ag_run("cut.room_width_m=2.5", "merge.cover_removed_obstacles=true"),
                                 "office_small")
        default = exported_json(self.ag_run(), "office_small")
        self.assertNotEqual(expected["nodes"], default["nodes"], "the options change nothing")
        for graph in (
                areagraph.segment(OFFICE, cut__room_width_m=2.5, merge__cover_removed_obstacles=True),
                areagraph.segment(OFFICE, **{"cut.room_width_m": "2.5",
                                             "merge.cover_removed_obstacles": "true"}),
                areagraph.segment(OFFICE, options={"cut.room_width_m": 2.5,
                                                   "merge.cover_removed_obstacles": True})):
            self.assertEqual(json.loads(graph._handle.node_link_json())["nodes"],
                             expected["nodes"])

    def test_an_options_file_acts_as_ag_run_options(self):
        options = os.path.join(self.dir, "options.pbtxt")
        with open(options, "w") as file:
            file.write("cut { room_width_m: 2.5 }\n")
        expected = exported_json(self.ag_run("cut.room_width_m=2.5"), "office_small")
        graph = areagraph.segment(OFFICE, options=options)
        self.assertEqual(json.loads(graph._handle.node_link_json())["nodes"], expected["nodes"])

    def test_a_ros_grid_gives_the_graph_of_the_same_cells(self):
        from_file = areagraph.segment(OFFICE)
        with areagraph.Store(self.ag_run()) as store:
            grid_map = store.artifact("office_small", "import")
        frame = grid_map.frame
        grid = ros_grid(grid_map)
        for cells in (grid, grid.astype(numpy.int8)):
            from_grid = areagraph.segment(cells, resolution=frame.resolution_m,
                                          origin=(frame.origin_x_m, frame.origin_y_m))
            self.assertEqual(from_grid.name, "grid")
            expected, got = node_link(from_file), node_link(from_grid)
            self.assertEqual(got["nodes"], expected["nodes"])
            self.assertEqual(got["links"], expected["links"])

    def test_a_pgm_goes_through_the_image_codecs_module(self):
        with areagraph.Store(self.ag_run()) as store:
            grid_map = store.artifact("office_small", "import")
        frame = grid_map.frame
        cells = numpy.frombuffer(grid_map.cells, dtype=numpy.uint8).reshape(frame.height_px,
                                                                            frame.width_px)
        pgm = os.path.join(self.dir, "office_small.pgm")
        with open(pgm, "wb") as file:
            file.write(b"P5\n%d %d\n255\n" % (frame.width_px, frame.height_px))
            file.write(numpy.choose(cells, [254, 0, 205]).astype(numpy.uint8).tobytes())
        with open(os.path.join(self.dir, "office_small.yaml"), "w") as file:
            file.write("image: office_small.pgm\nresolution: %r\norigin: [%r, %r, 0.0]\n"
                       "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n" %
                       (frame.resolution_m, frame.origin_x_m, frame.origin_y_m))
        self.assertEqual(node_link(areagraph.segment(pgm)), node_link(areagraph.segment(OFFICE)))

    def test_origin_and_resolution_place_an_image_without_yaml(self):
        image = os.path.join(self.dir, "plain.png")
        with open(OFFICE, "rb") as source, open(image, "wb") as copy:
            copy.write(source.read())
        at_zero = areagraph.segment(image)
        moved = areagraph.segment(image, origin=(100, -50))
        self.assertEqual(len(at_zero.areas), len(moved.areas))
        for a, b in zip(at_zero.areas, moved.areas):
            self.assertAlmostEqual(b.area_m2, a.area_m2, places=6)
            self.assertAlmostEqual(b.centroid[0], 100 + a.centroid[0], places=6)
            self.assertAlmostEqual(b.centroid[1], -50 + a.centroid[1], places=6)
        store = os.path.join(self.dir, "plain.db")
        run_tool("ag-run", "--store", store, "--jobs", "1", "--set", "import.resolution_m=0.04",
                 image)
        coarse = areagraph.segment(image, resolution=0.04)
        self.assertEqual(json.loads(coarse._handle.node_link_json()), exported_json(store, "plain"))

    def test_errors_carry_the_tools_messages(self):
        missing = os.path.join(self.dir, "missing.png")
        store = os.path.join(self.dir, "errors.db")
        with self.assertRaises(areagraph.InputError) as caught:
            areagraph.segment(missing)
        self.assertEqual(str(caught.exception), tool_error("ag-import", "--store", store, missing))
        self.assertIsInstance(caught.exception, areagraph.Error)

        with self.assertRaises(areagraph.OptionsError) as caught:
            areagraph.segment(OFFICE, cut__room_width_m=-1)
        self.assertEqual(str(caught.exception),
                         tool_error("ag-run", "--store", store, "--set", "cut.room_width_m=-1",
                                    OFFICE))
        with self.assertRaises(areagraph.OptionsError) as caught:
            areagraph.segment(OFFICE, **{"cut.no_such_option": 1})
        self.assertEqual(str(caught.exception),
                         tool_error("ag-run", "--store", store, "--set", "cut.no_such_option=1",
                                    OFFICE))
        with self.assertRaises(areagraph.OptionsError) as caught:
            areagraph.segment(OFFICE, resolution=0.1)
        self.assertIn("contradicts resolution 0.05", str(caught.exception))

    def test_bad_grids_are_input_errors(self):
        with self.assertRaisesRegex(areagraph.InputError, "2-D array"):
            areagraph.segment(numpy.zeros((4, 4, 3), dtype=numpy.uint8))
        with self.assertRaisesRegex(areagraph.InputError, "uint8 or int8"):
            areagraph.segment(numpy.zeros((4, 4), dtype=numpy.float32))
        cells = numpy.zeros((4, 5), dtype=numpy.uint8)
        cells[2, 3] = 150
        with self.assertRaises(areagraph.InputError) as caught:
            areagraph.segment(cells)
        self.assertEqual(str(caught.exception),
                         "grid cell (row 2, column 3) holds 150; valid are 0..100 (percent "
                         "occupied) and 255 (unknown)")
        with self.assertRaisesRegex(areagraph.InputError, "takes a map file's path"):
            areagraph.segment(42)

    def test_area_at_finds_each_area_and_nothing_outside(self):
        graph = areagraph.segment(OFFICE)
        for area in graph.areas:
            point = area.polygon.representative_point()
            self.assertIs(graph.area_at(point.x, point.y), area)
        self.assertIsNone(graph.area_at(-1000, -1000))

    def test_polygons_and_passages_are_shapely_in_metres(self):
        graph = areagraph.segment(OFFICE)
        for area in graph.areas:
            self.assertTrue(area.polygon.is_valid)
            self.assertAlmostEqual(area.polygon.area, area.area_m2, delta=1e-6 * area.area_m2)
            self.assertIn(area.kind, ("room", "corridor", "dead_end"))
        stable_ids = {area.stable_id for area in graph.areas}
        for passage in graph.passages:
            self.assertTrue(set(passage.areas) <= stable_ids)
            a, b = (next(x for x in graph.areas if x.stable_id == s) for s in passage.areas)
            self.assertLess(passage.border.distance(a.polygon.exterior), 1e-9)
            self.assertLess(passage.border.distance(b.polygon.exterior), 1e-9)
            self.assertGreater(passage.width_m, 0)
        self.assertEqual(len(graph.message.areas), len(graph.areas))


if __name__ == "__main__":
    unittest.main()
