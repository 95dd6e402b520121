"""Compares the exports of two versions of one map (a re-run with other
options): every area that kept its shape (in GeoJSON) must keep its id in
each format, and so must every passage that kept its place between the same
two areas.

Usage: check_rerun_ids.py FIRST_DIR SECOND_DIR
Each folder holds map.geojson, map.json (node-link) and map.osm (osmAG) of
one version, written without an anchor. Prints "kept <n> of <m> areas and
<p> of <q> passages: <area ids>" and exits 0, or prints the first id that
changed and exits 1.
"""
import json
import math
import sys
import xml.etree.ElementTree as ElementTree

from shapely.geometry import LineString, Polygon, shape

# An area keeps its shape when its polygons before and after differ by less
# than this share of their union (outlines are simplified within 0.1 m, so
# an unchanged room's outline can move by a vertex).
SAME_SHAPE_IOU = 0.98
# Two areas are the same area grown or shrunk above this share.
SAME_AREA_IOU = 0.5
# A passage keeps its place when its middle moved less than this (ag-match
# keeps a passage's id within 1 m).
SAME_PLACE_M = 0.25
EARTH_RADIUS_M = 6378137.0


def fail(message):
    print("check_rerun_ids: " + message, file=sys.stderr)
    sys.exit(1)


def geojson_ids(folder):
    """Areas: id -> polygon; passages: id -> (line, from, to)."""
    with open(folder + "/map.geojson") as f:
        features = json.load(f)["features"]
    areas, passages = {}, {}
    for feature in features:
        props = feature["properties"]
        if props["layer"] == "area":
            areas[props["area_id"]] = shape(feature["geometry"])
        else:
            passages[props["passage_id"]] = (LineString(feature["geometry"]["coordinates"]),
                                             props["from"], props["to"])
    return areas, passages


def node_link_ids(folder):
    with open(folder + "/map.json") as f:
        graph = json.load(f)
    areas = {node["id"]: Polygon(node["polygon"], node["holes"]) for node in graph["nodes"]}
    passages = {link["key"]: (LineString(link["border"]), link["source"], link["target"])
                for link in graph["links"]}
    return areas, passages


def osmag_ids(folder):
    osm = ElementTree.parse(folder + "/map.osm").getroot()
    tags_of = lambda e: {t.get("k"): t.get("v") for t in e.findall("tag")}
    nodes = {n.get("id"): (float(n.get("lat")), float(n.get("lon"))) for n in osm.findall("node")}
    root = [n for n in osm.findall("node") if tags_of(n).get("name") == "root"][0]
    lat0, lon0 = nodes[root.get("id")]
    scale_x = math.radians(1) * EARTH_RADIUS_M * math.cos(math.radians(lat0))
    scale_y = math.radians(1) * EARTH_RADIUS_M
    ways = {w.get("id"): [nd.get("ref") for nd in w.findall("nd")] for w in osm.findall("way")}
    points = lambda refs: [((nodes[r][1] - lon0) * scale_x, (nodes[r][0] - lat0) * scale_y)
                           for r in refs]
    number = lambda name, prefix: int(name[len(prefix):])
    areas, passages = {}, {}
    for way in osm.findall("way"):
        tags = tags_of(way)
        if tags.get("osmAG:type") == "area" and tags.get("osmAG:areaType") == "room":
            areas[number(tags["name"], "area_")] = Polygon(points(ways[way.get("id")]))
        elif tags.get("osmAG:type") == "passage":
            passages[number(tags["name"], "passage_")] = (
                LineString(points(ways[way.get("id")])), number(tags["osmAG:from"], "area_"),
                number(tags["osmAG:to"], "area_"))
    for relation in osm.findall("relation"):
        tags = tags_of(relation)
        rings = {"outer": [], "inner": []}
        for member in relation.findall("member"):
            rings[member.get("role")].append(points(ways[member.get("ref")]))
        areas[number(tags["name"], "area_")] = Polygon(rings["outer"][0], rings["inner"])
    return areas, passages


def iou(a, b):
    union = a.union(b).area
    return a.intersection(b).area / union if union > 0 else 0


def same_place(a, b):
    return a.interpolate(0.5, normalized=True).distance(
        b.interpolate(0.5, normalized=True)) < SAME_PLACE_M


def kept_shapes(first, second):
    """The areas (by id in the second version) whose shape stayed, and the
    passages that stayed in place between the same areas; fails if one of
    them changed its id."""
    (areas1, passages1), (areas2, passages2) = first, second
    kept_areas = set()
    for id2, polygon2 in areas2.items():
        for id1, polygon1 in areas1.items():
            if iou(polygon1, polygon2) >= SAME_SHAPE_IOU:
                if id1 != id2:
                    fail("geojson: an area kept its shape but its id went from %d to %d" %
                         (id1, id2))
                kept_areas.add(id2)
    # A passage stays where it was when its two areas are still mostly the
    # same areas (they may have grown or shrunk) and it lies where it lay.
    same_area = {}
    for id2, polygon2 in areas2.items():
        best = max(areas1, key=lambda id1: iou(areas1[id1], polygon2), default=None)
        if best is not None and iou(areas1[best], polygon2) >= SAME_AREA_IOU:
            same_area[id2] = best
    kept_passages = set()
    for id2, (line2, a2, b2) in passages2.items():
        if a2 not in same_area or b2 not in same_area:
            continue
        for id1, (line1, a1, b1) in passages1.items():
            if {a1, b1} == {same_area[a2], same_area[b2]} and same_place(line1, line2):
                if id1 != id2:
                    fail("geojson: a passage kept its place but its id went from %d to %d" %
                         (id1, id2))
                kept_passages.add(id2)
    return kept_areas, kept_passages


def check_format(fmt, first, second, kept_areas, kept_passages):
    """In another format, the kept areas and passages have the same ids in
    both versions, with the same shape and place."""
    (areas1, passages1), (areas2, passages2) = first, second
    for id in sorted(kept_areas):
        if id not in areas1 or id not in areas2 or iou(areas1[id], areas2[id]) < SAME_SHAPE_IOU / 2:
            fail("%s: area %d kept its shape, but not its id" % (fmt, id))
    for id in sorted(kept_passages):
        if id not in passages1 or id not in passages2 or \
                {passages1[id][1], passages1[id][2]} != {passages2[id][1], passages2[id][2]} or \
                not same_place(passages1[id][0], passages2[id][0]):
            fail("%s: passage %d kept its place, but not its id" % (fmt, id))


def main():
    first, second = sys.argv[1], sys.argv[2]
    geojson = geojson_ids(first), geojson_ids(second)
    kept_areas, kept_passages = kept_shapes(*geojson)
    for fmt, read in (("json", node_link_ids), ("osmag", osmag_ids)):
        check_format(fmt, read(first), read(second), kept_areas, kept_passages)
    print("kept %d of %d areas and %d of %d passages: %s" %
          (len(kept_areas), len(geojson[1][0]), len(kept_passages), len(geojson[1][1]),
           " ".join(str(i) for i in sorted(kept_areas))))


if __name__ == "__main__":
    main()
