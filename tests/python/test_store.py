"""areagraph.Store: maps, Area Graphs (newest or by version), artifacts as protobuf messages and
the history, from stores that ag-run wrote."""

import json
import os
import unittest

import areagraph
from python_test_support import TempDirTest, example, exported_json, run_tool, tool_error

OFFICE = example("office_small.png")


def nodes(graph):
    return json.loads(graph._handle.node_link_json())["nodes"]


class StoreTest(TempDirTest):

    def setUp(self):
        super().setUp()
        self.store = os.path.join(self.dir, "areagraph.db")
        run_tool("ag-run", "--store", self.store, "--jobs", "1", OFFICE)
        self.first = exported_json(self.store, "office_small")
        # Other options make a second version of the map's graph.
        run_tool("ag-run", "--store", self.store, "--jobs", "1", "--set", "cut.room_width_m=2.5",
                 OFFICE)
        self.second = exported_json(self.store, "office_small")

    def test_maps_graphs_and_versions(self):
        with areagraph.Store(self.store) as store:
            self.assertEqual(store.maps(), ["office_small"])
            self.assertEqual(nodes(store.area_graph("office_small")), self.second["nodes"])
            self.assertEqual(nodes(store.area_graph("office_small", version=1)),
                             self.first["nodes"])
            self.assertEqual(nodes(store.area_graph("office_small", "head")),
                             self.second["nodes"])
            self.assertEqual(store.area_graph("office_small", 1).version, 1)
            history = store.history("office_small")
            self.assertEqual([v.number for v in history], [1, 2])
            self.assertEqual([v.head for v in history], [False, True])
            self.assertEqual(history[1].predecessor_key, history[0].key)
            self.assertTrue(all(v.stored for v in history))
            key_prefix = history[0].key[:12]
            self.assertEqual(nodes(store.area_graph("office_small", key_prefix)),
                             self.first["nodes"])

    def test_artifacts_are_protobuf_messages(self):
        with areagraph.Store(self.store) as store:
            grid = store.artifact("office_small", "import")
            self.assertEqual(grid.DESCRIPTOR.full_name, "areagraph.proto.GridMap")
            self.assertEqual(len(grid.cells), grid.frame.width_px * grid.frame.height_px)
            cleaned = store.artifact("office_small", "clean")
            self.assertEqual(cleaned.DESCRIPTOR.full_name, "areagraph.proto.CleanedMap")
            graph = store.artifact("office_small", "match")
            self.assertEqual(len(graph.areas), len(self.second["nodes"]))
            self.assertEqual(graph.version.number, 2)
            topology = store.artifact("office_small", "prune")
            self.assertGreater(len(topology.edges), 0)

    def test_errors_carry_the_tools_messages(self):
        with areagraph.Store(self.store) as store:
            with self.assertRaises(areagraph.InputError) as caught:
                store.area_graph("nowhere")
            self.assertEqual(str(caught.exception), tool_error(
                "ag-export", "--store", self.store, "--map", "nowhere", "--format", "json",
                "--out", "-"))
            with self.assertRaises(areagraph.InputError) as caught:
                store.area_graph("office_small", 7)
            self.assertEqual(str(caught.exception), tool_error(
                "ag-route", "--store", self.store, "--map", "office_small", "--from", "0,0",
                "--to", "1,1", "--graph-version", "7"))
            with self.assertRaises(areagraph.OptionsError) as caught:
                store.artifact("office_small", "doors")
            # The tool names its flag, Python the argument.
            self.assertEqual("--" + str(caught.exception), tool_error(
                "ag-render", "--store", self.store, "--map", "office_small", "--stage", "doors",
                "--out", os.path.join(self.dir, "x.png")))
            with self.assertRaises(areagraph.InputError):
                store.history("nowhere")
        with self.assertRaises(areagraph.StoreError):
            store.maps()
        not_a_store = os.path.join(self.dir, "text.db")
        with open(not_a_store, "w") as file:
            file.write("not SQLite at all, just some text")
        with self.assertRaises(areagraph.StoreError) as caught:
            areagraph.Store(not_a_store).maps()
        self.assertEqual(str(caught.exception), tool_error(
            "ag-inspect", "--store", not_a_store))


if __name__ == "__main__":
    unittest.main()
