"""Reads osmAG files from ag-export and checks their areas as geometry, as
a GIS would read them: every area (a closed way, or a multipolygon
relation: its outer rings minus its inner rings) is made of simple rings,
its outer rings do not overlap one another, its inner rings lie inside
them without overlapping one another, and no two areas overlap (the union
of all areas is as large as the sum of their areas).

Usage: check_osmag_geometry.py FILE...
Prints "<file>: <areas> areas (<holed> multipolygons), <m2> m2, overlap
<m2> m2" per file and exits 0, or prints the first broken rule and exits 1.
"""
import math
import sys
import xml.etree.ElementTree as ElementTree

from shapely.geometry import LinearRing, Polygon
from shapely.ops import unary_union

EARTH_RADIUS_M = 6378137.0
# Neighbours share their border's nodes, so the union of areas that tile
# loses only floating-point noise; an overlap that matters is far larger.
MAX_OVERLAP_M2 = 0.01


def tags_of(element):
    return {tag.get("k"): tag.get("v") for tag in element.findall("tag")}


def overlap(polygons):
    return sum(p.area for p in polygons) - unary_union(polygons).area


def area_geometry(path, name, outers, inners):
    """The area as outers minus inners, after checking the rings."""
    for points in outers + inners:
        if len(points) < 4 or points[0] != points[-1] or not LinearRing(points).is_simple:
            sys.exit("%s: %s has a ring that is not simple and closed" % (path, name))
    outer = [Polygon(points) for points in outers]
    inner = [Polygon(points) for points in inners]
    if overlap(outer) > MAX_OVERLAP_M2 or overlap(inner) > MAX_OVERLAP_M2:
        sys.exit("%s: %s has rings of one role that overlap" % (path, name))
    outside = unary_union(inner).difference(unary_union(outer)).area if inner else 0
    if outside > MAX_OVERLAP_M2:
        sys.exit("%s: %s has an inner ring outside its outer rings" % (path, name))
    return unary_union(outer).difference(unary_union(inner)) if inner else unary_union(outer)


def check(path):
    osm = ElementTree.parse(path).getroot()
    nodes = {n.get("id"): (float(n.get("lat")), float(n.get("lon"))) for n in osm.findall("node")}
    root = [n for n in osm.findall("node") if tags_of(n).get("name") == "root"]
    lat0, lon0 = nodes[root[0].get("id")]
    scale_x = math.radians(1) * EARTH_RADIUS_M * math.cos(math.radians(lat0))
    scale_y = math.radians(1) * EARTH_RADIUS_M
    ways = {w.get("id"): [nd.get("ref") for nd in w.findall("nd")] for w in osm.findall("way")}

    def ring(way):
        return [((nodes[r][1] - lon0) * scale_x, (nodes[r][0] - lat0) * scale_y) for r in ways[way]]

    areas = {}
    for way in osm.findall("way"):
        tags = tags_of(way)
        if tags.get("osmAG:type") == "area" and tags.get("osmAG:areaType") != "structure":
            areas[tags["name"]] = area_geometry(path, tags["name"], [ring(way.get("id"))], [])
    multipolygons = 0
    for relation in osm.findall("relation"):
        tags = tags_of(relation)
        if tags.get("type") != "multipolygon" or tags.get("osmAG:type") != "area":
            continue
        rings = {"outer": [], "inner": []}
        for member in relation.findall("member"):
            rings[member.get("role")].append(ring(member.get("ref")))
        areas[tags["name"]] = area_geometry(path, tags["name"], rings["outer"], rings["inner"])
        multipolygons += 1
    for name, geometry in areas.items():
        if not geometry.is_valid or geometry.is_empty:
            sys.exit("%s: %s is not a valid area" % (path, name))
    total = sum(g.area for g in areas.values())
    overlapping = overlap(list(areas.values()))
    print("%s: %d areas (%d multipolygons), %.1f m2, overlap %.3f m2" %
          (path, len(areas), multipolygons, total, overlapping + 0.0))
    if overlapping > MAX_OVERLAP_M2:
        sys.exit("%s: the areas overlap by %.3f m2" % (path, overlapping))


for path in sys.argv[1:]:
    check(path)
