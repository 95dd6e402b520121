"""Area Graphs of 2D occupancy grid maps of buildings: areas (rooms, corridors, dead ends) with
their polygons, and the passages (doors, openings) between them.

    import areagraph

    graph = areagraph.segment("lab_a.png")           # PNG, PGM or map_server YAML
    print(len(graph.areas), graph.areas[0].polygon.area)
    nx_graph = graph.to_networkx()                    # a networkx MultiGraph
    route = graph.route((1.0, 2.0), (14.5, 3.0))      # None when unreachable
    print(route.length_m, route.areas, route.polyline)

    with areagraph.Store("areagraph.db") as store:    # what ag-run wrote
        graph = store.area_graph("lab_a")

segment() runs the pipeline that ag-run runs (import, clean, voronoi, prune, cut, merge, match),
in this process, with the same defaults; `options` and `**set` change them as ag-run's
--options and --set do. Coordinates are metres in the map frame of ROS's map_server (x right,
y up, the origin at the image's bottom-left corner). Polygons and lines are shapely objects;
the graph as a whole is a networkx MultiGraph.

Every error is an areagraph.Error (InputError, OptionsError, StoreError, MapStepError) whose
message is the line that the command-line tools print.
"""

import os

from . import _core
from ._core import Error, InputError, MapStepError, OptionsError, StoreError
from .graph import Area, AreaGraph, Passage, Route
from .store import Store, Version

__all__ = [
    "segment", "AreaGraph", "Area", "Passage", "Route", "Store", "Version", "Error", "InputError",
    "OptionsError", "StoreError", "MapStepError",
]

for _error in (Error, InputError, OptionsError, StoreError, MapStepError):
    _error.__module__ = __name__

_DEFAULT_RESOLUTION = 0.05
_DEFAULT_ORIGIN = (0, 0)


def segment(map_path_or_array, resolution=0.05, origin=(0, 0), options=None, **set):
    """Segments a map into its Area Graph, as ag-run does, and returns an AreaGraph.

    map_path_or_array: a PNG or PGM image (a map_server YAML of the same stem beside it is
        applied, as ag-import does) or a map_server YAML file; or a 2-D uint8 or int8 numpy
        array in ROS's OccupancyGrid convention: row 0 at the origin (the bottom of the map),
        values 0 to 100 percent occupied and 255 (-1) unknown, classified as ag-live does
        (at most 25 free, at least 65 occupied, unknown between).
    resolution: metres per cell. A YAML's resolution applies to its image; giving another
        value here is an OptionsError.
    origin: (x, y) in metres of the map's bottom-left corner; the same holds for a YAML's.
    options: a PipelineOptions file in protobuf text format (ag-run --options; see
        examples/options/default.pbtxt), or a dict of overrides like **set.
    **set: option overrides as with ag-run --set, e.g. segment(path, cut__room_width_m=1.1)
        or segment(path, **{"cut.room_width_m": 1.1}).

    An image is named after its file's stem (AreaGraph.name); an array is named "grid".
    Raises InputError (a bad file or grid), OptionsError (a bad option) or MapStepError (a
    stage failed: "map 'M', STAGE: cause").
    """
    overrides = []
    options_file = ""
    if isinstance(options, dict):
        overrides += [_assignment(key, value) for key, value in options.items()]
    elif options is not None:
        options_file = os.fspath(options)
    overrides += [_assignment(key, value) for key, value in set.items()]
    if isinstance(map_path_or_array, (str, bytes, os.PathLike)):
        path = os.fsdecode(map_path_or_array)
        handle = _core.segment_file(
            path, None if resolution == _DEFAULT_RESOLUTION else float(resolution),
            None if tuple(origin) == _DEFAULT_ORIGIN else _pair(origin), options_file, overrides)
    elif getattr(map_path_or_array, "ndim", None) is not None:
        handle = _core.segment_grid(map_path_or_array, float(resolution), _pair(origin),
                                    options_file, overrides, "grid")
    else:
        raise InputError("segment() takes a map file's path or a 2-D numpy array, not %s" %
                         type(map_path_or_array).__name__)
    return AreaGraph(handle)


def _assignment(key, value):
    """'stage.field=value' for ag-run's --set, from a key with '.' or '__' between the parts."""
    if isinstance(value, bool):
        value = "true" if value else "false"
    return "%s=%s" % (key.replace("__", "."), value)


def _pair(xy):
    x, y = xy
    return (float(x), float(y))
