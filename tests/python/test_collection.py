"""areagraph.Store on a collection index (ag-store index over shard stores): the same maps,
graphs, artifacts and history as the unsharded store, and the tools' message for a missing
shard."""

import os
import shutil

import areagraph
from python_test_support import TempDirTest, example, exported_json, run_tool, tool_error


class CollectionTest(TempDirTest):

    def setUp(self):
        super().setUp()
        self.maps = os.path.join(self.dir, "maps")
        os.makedirs(self.maps)
        for name in ("office_small.png", "corridor_rooms.png", "two_rooms.png"):
            shutil.copy(example(name), self.maps)
        self.whole = os.path.join(self.dir, "whole.db")
        run_tool("ag-run", "--store", self.whole, "--jobs", "1", self.maps)
        self.folder = os.path.join(self.dir, "collection")
        os.makedirs(self.folder)
        # Three shards: the maps' names hash to shard 1 (one map) and 2 (two).
        shards = [os.path.join(self.folder, "shard-%d.db" % k) for k in range(3)]
        for k, shard in enumerate(shards):
            run_tool("ag-run", "--store", shard, "--shard", "%d/3" % k, "--jobs", "1", self.maps)
        self.index = os.path.join(self.folder, "collection.db")
        run_tool("ag-store", "index", "--out", self.index, *shards)

    def test_reads_as_the_whole_store(self):
        with areagraph.Store(self.index) as store, areagraph.Store(self.whole) as whole:
            self.assertEqual(store.maps(), whole.maps())
            self.assertEqual(len(store.maps()), 3)
            for name in whole.maps():
                self.assertEqual(store.area_graph(name)._handle.node_link_json(),
                                 whole.area_graph(name)._handle.node_link_json())
                self.assertEqual(store.artifact(name, "clean"), whole.artifact(name, "clean"))
                self.assertEqual([v.number for v in store.history(name)], [1])
                self.assertEqual(store.history(name)[0].key, whole.history(name)[0].key)
            name = whole.maps()[0]
            self.assertEqual(len(store.area_graph(name).areas),
                             len(exported_json(self.whole, name)["nodes"]))

    def test_missing_shard_is_named_as_the_tools_name_it(self):
        with areagraph.Store(self.index) as store:
            names = store.maps()
        os.remove(os.path.join(self.folder, "shard-2.db"))
        with areagraph.Store(self.index) as store:
            self.assertEqual(store.maps(), names)  # the index itself still lists them
            failed = 0
            for name in names:
                try:
                    store.area_graph(name)
                except areagraph.StoreError as caught:
                    failed += 1
                    self.assertIn(name, str(caught))
                    self.assertIn("is in shard store 'shard-2.db' of collection index", str(caught))
                    self.assertEqual(str(caught), tool_error(
                        "ag-export", "--store", self.index, "--map", name, "--format", "json",
                        "--out", "-"))
            self.assertEqual(failed, 2)  # the map of shard 1 still reads
