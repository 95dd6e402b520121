"""Reading a store that ag-run, ag-live or the stage executables wrote."""

import os
from typing import NamedTuple

from . import _core, _messages
from .graph import AreaGraph


class Version(NamedTuple):
    """One version of a map's Area Graph in the store's history (Store.history)."""

    number: int
    """1 for the map's first Area Graph, then one more than its predecessor's."""
    key: str
    """The cache key of its artifact (ag-match's)."""
    predecessor_key: str
    """The key of the version before it; empty for the first."""
    created_at: str
    """When it was made, UTC, ISO 8601."""
    stored: bool
    """False when ag-store gc dropped it (its row stays in the history)."""
    head: bool
    """Whether it is the map's current Area Graph."""


class Store:
    """An areagraph store (one SQLite file), or a collection index of shard stores (ag-store
    index; docs/collections.md), opened read-only.

        with areagraph.Store("areagraph.db") as store:
            for map_name in store.maps():
                print(map_name, store.area_graph(map_name))

    Raises StoreError when the file is not a store or cannot be read.
    """

    def __init__(self, path):
        self._reader = _core.StoreReader(os.fsdecode(path))

    def maps(self):
        """The names of the maps in the store (list of str), sorted."""
        return sorted(self._reader.maps())

    def area_graph(self, map, version=None):
        """The map's Area Graph as an AreaGraph: the newest (as ag-export picks it: ag-match's,
        unless ag-merge ran after it) or the given version: a number from history(), a key or
        key prefix, or "head". Raises InputError when the map, its graph or the version is not
        in the store."""
        return AreaGraph(self._reader.area_graph(map, "" if version is None else str(version)))

    def artifact(self, map, stage):
        """The head artifact of one stage of the map ("import", "clean", "voronoi", "prune",
        "cut", "merge" or "match") as its protobuf message (GridMap, CleanedMap, VoronoiDiagram,
        TopologyGraph, CutGraph or AreaGraph; see proto/artifacts.proto)."""
        type_name, payload = self._reader.artifact(map, stage)
        return _messages.parse(type_name, payload)

    def history(self, map):
        """The versions of the map's Area Graph (list of Version), oldest first; empty when
        ag-match has not run on it."""
        return [Version(*row) for row in self._reader.history(map)]

    def close(self):
        """Closes the store; the object cannot read after."""
        self._reader.close()

    def __enter__(self):
        return self

    def __exit__(self, *exception):
        self.close()
