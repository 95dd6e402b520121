"""Reads an areagraph store (SQLite) from Python and turns Area Graphs into networkx graphs.

The protobuf message classes are built from the descriptor set that the build writes
(build/python/areagraph_descriptors.pb: every .proto of the project, with imports), so
they live under our own names (areagraph.proto.AreaGraph, ...) and nothing needs to be
generated or installed. Needs Debian's python3-protobuf and python3-zstandard (payloads
are zstd frames since store schema 5); to_networkx needs python3-networkx.
"""

import sqlite3

import zstandard

from google.protobuf import descriptor_pb2, message_factory

# Area kinds as every export names them.
KIND_NAMES = {"AREA_ROOM": "room", "AREA_CORRIDOR": "corridor", "AREA_DEAD_END": "dead_end"}


def load_message_classes(descriptor_path):
    """Message classes of the descriptor set at descriptor_path, by full name."""
    with open(descriptor_path, "rb") as file:
        descriptors = descriptor_pb2.FileDescriptorSet.FromString(file.read())
    return message_factory.GetMessages(descriptors.file)


class MissingArtifact(LookupError):
    """A map or stage that the store does not hold."""


class AreagraphStore:
    """A store opened read-only. See store/README.md for its tables."""

    def __init__(self, store_path, descriptor_path):
        self._db = sqlite3.connect(f"file:{store_path}?mode=ro", uri=True)
        (schema,) = self._db.execute("PRAGMA user_version").fetchone()
        # Schema 5 added artifacts.payload_codec (0 raw, 1 zstd); older rows are raw.
        self._codec_column = "a.payload_codec" if schema >= 5 else "0"
        self._classes = load_message_classes(descriptor_path)

    def maps(self):
        """The names of the maps in the store."""
        return [name for (name,) in self._db.execute("SELECT name FROM maps ORDER BY name")]

    def head(self, map_name, stage):
        """The head artifact of (map, stage), parsed; MissingArtifact when there is none."""
        row = self._db.execute(
            f"SELECT a.proto_type, a.payload, {self._codec_column} FROM maps m"
            " JOIN heads h ON h.map_id = m.id JOIN artifacts a ON a.id = h.artifact_id"
            " WHERE m.name = ? AND h.stage = ?", (map_name, stage)).fetchone()
        if row is None:
            raise MissingArtifact(f"map '{map_name}' has no {stage} artifact")
        proto_type, payload, codec = row
        if codec == 1:
            payload = zstandard.ZstdDecompressor().decompress(payload)
        elif codec != 0:
            raise ValueError(f"map '{map_name}', {stage}: unknown payload codec {codec}")
        message = self._classes[proto_type]()
        message.ParseFromString(payload)
        return message

    def area_graph(self, map_name):
        """The map's newest Area Graph, as ag-export picks it: the match head (with stable ids)
        when it was made from the merge head, else the merge head (match has not run since)."""
        heads = {stage: (key, inputs.split("\n")) for stage, key, inputs in self._db.execute(
            "SELECT h.stage, a.cache_key, a.input_keys FROM maps m"
            " JOIN heads h ON h.map_id = m.id JOIN artifacts a ON a.id = h.artifact_id"
            " WHERE m.name = ? AND h.stage IN ('match', 'merge')", (map_name,))}
        if "match" in heads and ("merge" not in heads or heads["merge"][0] in heads["match"][1]):
            return self.head(map_name, "match")
        return self.head(map_name, "merge")


def to_networkx(graph):
    """The Area Graph as an undirected networkx MultiGraph: a node per area, an edge per passage
    (two areas may share several passages, so parallel edges are kept). Attribute names are those
    of `ag-export --format json` (rings here as stored, there oriented counter-clockwise)."""
    import networkx

    kinds = graph.DESCRIPTOR.fields_by_name["areas"].message_type.fields_by_name["kind"].enum_type
    result = networkx.MultiGraph()
    # A graph from ag-match also has stable ids (the same across the map's versions).
    stable = graph.HasField("version")
    if stable:
        result.graph["version"] = graph.version.number
    for area in graph.areas:
        result.add_node(
            area.id,
            **({"stable_id": area.stable_id} if stable else {}),
            name="area_%d" % area.id,
            kind=KIND_NAMES.get(kinds.values_by_number[area.kind].name, "unknown"),
            area_m2=area.area_m2,
            centroid=(area.centroid_m.x, area.centroid_m.y),
            polygon=[(p.x, p.y) for p in area.polygon_m.outer.points],
            holes=[[(p.x, p.y) for p in hole.points] for hole in area.polygon_m.holes])
    for passage in graph.passages:
        result.add_edge(
            passage.area_a, passage.area_b, key=passage.id,
            id=passage.id,
            **({"stable_id": passage.stable_id} if stable else {}),
            name="passage_%d" % passage.id,
            width_m=passage.width_m,
            point=(passage.point_m.x, passage.point_m.y),
            border=[(p.x, p.y) for p in passage.border_m] or
            [(passage.segment_m.a.x, passage.segment_m.a.y),
             (passage.segment_m.b.x, passage.segment_m.b.y)])
    return result
