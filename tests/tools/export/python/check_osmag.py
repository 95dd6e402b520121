"""Checks an osmAG file from ag-export against the osmAG rules: areas are
closed ways, or multipolygon relations (outer and inner rings) for areas
with holes, under one structure area; passages are ways over nodes of both
areas' rings, tagged as osmAG passages and as nothing JOSM reads as a door.

Usage: check_osmag.py FILE --map NAME --level N [--height M] [--anchor LAT LON]
Prints "<areas> areas, <passages> passages, <shared> passage nodes shared"
and exits 0, or prints the first broken rule and exits 1.
"""
import argparse
import sys
import xml.etree.ElementTree as ElementTree


def fail(message):
    print("check_osmag: " + message, file=sys.stderr)
    sys.exit(1)


def tags_of(element):
    return {tag.get("k"): tag.get("v") for tag in element.findall("tag")}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("file")
    parser.add_argument("--map", required=True)
    parser.add_argument("--level", required=True)
    parser.add_argument("--height")
    parser.add_argument("--anchor", nargs=2, type=float)
    args = parser.parse_args()

    osm = ElementTree.parse(args.file).getroot()
    if osm.tag != "osm" or osm.get("version") != "0.6" or osm.get("upload") != "never":
        fail("root element must be <osm version=\"0.6\" upload=\"never\">")
    nodes = {n.get("id"): n for n in osm.findall("node")}
    ways = osm.findall("way")
    refs_of = {w.get("id"): [nd.get("ref") for nd in w.findall("nd")] for w in ways}
    ids = [e.get("id") for e in osm if e.tag in ("node", "way", "relation")]
    if len(set(ids)) != len(ids) or any(int(i) >= 0 for i in ids):
        fail("ids must be negative (new objects) and unique")

    roots = [n for n in nodes.values() if tags_of(n).get("name") == "root"]
    if len(roots) != 1 or tags_of(roots[0]).get("osmAG:map") != args.map:
        fail("one root node named root with osmAG:map=" + args.map)
    if args.anchor and (abs(float(roots[0].get("lat")) - args.anchor[0]) > 1e-9 or
                        abs(float(roots[0].get("lon")) - args.anchor[1]) > 1e-9):
        fail("the root node must lie at the anchor")

    # Areas by name: their tags and the nodes of each of their rings.
    areas, structures, passages, ring_ways = {}, [], [], set()
    for relation in osm.findall("relation"):
        tags = tags_of(relation)
        if tags.get("type") != "multipolygon" or tags.get("osmAG:type") != "area":
            fail("relation %s is not an osmAG area multipolygon" % relation.get("id"))
        if tags.get("level") != args.level:
            fail("relation %s lacks level=%s" % (relation.get("id"), args.level))
        members = relation.findall("member")
        roles = [m.get("role") for m in members]
        if roles.count("outer") != 1 or roles.count("inner") < 1 or \
                any(r not in ("outer", "inner") for r in roles):
            fail("relation %s needs one outer and inner rings" % relation.get("id"))
        rings = []
        for member in members:
            refs = refs_of.get(member.get("ref"))
            if member.get("type") != "way" or refs is None:
                fail("relation %s has a member that is not a way" % relation.get("id"))
            if len(refs) < 4 or refs[0] != refs[-1]:
                fail("ring %s of relation %s is not closed" % (member.get("ref"),
                                                              relation.get("id")))
            ring_ways.add(member.get("ref"))
            rings.append(refs)
        areas[tags.get("name")] = (tags, rings)
    for way in ways:
        tags = tags_of(way)
        refs = refs_of[way.get("id")]
        if any(ref not in nodes for ref in refs):
            fail("way %s refers to a missing node" % way.get("id"))
        if way.get("id") in ring_ways:
            if tags:
                fail("ring %s of a multipolygon carries tags" % way.get("id"))
            continue
        if tags.get("level") != args.level:
            fail("way %s lacks level=%s" % (way.get("id"), args.level))
        if tags.get("osmAG:type") == "area":
            if len(refs) < 4 or refs[0] != refs[-1]:
                fail("area way %s is not closed" % way.get("id"))
            if tags.get("osmAG:areaType") == "structure":
                structures.append((tags, refs))
            else:
                areas[tags.get("name")] = (tags, [refs])
        elif tags.get("osmAG:type") == "passage":
            passages.append((tags, refs))
        else:
            fail("way %s has no osmAG:type area or passage" % way.get("id"))

    if len(structures) != 1:
        fail("exactly one structure area (osmAG:areaType=structure)")
    structure_tags, structure_refs = structures[0]
    lats = [float(nodes[r].get("lat")) for r in structure_refs]
    lons = [float(nodes[r].get("lon")) for r in structure_refs]
    for name, (tags, rings) in areas.items():
        if tags.get("osmAG:areaType") not in ("room", "stairs", "elevator"):
            fail(name + ": osmAG:areaType must be room, stairs or elevator")
        if tags.get("areagraph:kind") not in ("room", "corridor", "dead_end"):
            fail(name + ": areagraph:kind must be room, corridor or dead_end")
        if tags.get("osmAG:parent") != structure_tags.get("name"):
            fail(name + ": osmAG:parent must name the structure area")
        if tags.get("indoor") != "room":
            fail(name + ": indoor=room")
        height = tags.get("height")
        if (height is None) != (args.height is None) or (
                height is not None and abs(float(height) - float(args.height)) > 1e-9):
            fail(name + ": height must be %s" % args.height)
        for ref in rings[0]:
            lat, lon = float(nodes[ref].get("lat")), float(nodes[ref].get("lon"))
            if not (min(lats) < lat < max(lats) and min(lons) < lon < max(lons)):
                fail(name + " is not inside the structure area")

    shared = 0
    for tags, refs in passages:
        name = tags.get("name")
        # JOSM reads these on a way as a door node in the wrong place.
        if any(key in tags for key in ("indoor", "door", "width")):
            fail(name + ": no indoor, door or width tag on a passage way")
        ends = [tags.get("osmAG:from"), tags.get("osmAG:to")]
        if any(end not in areas for end in ends) or ends[0] == ends[1]:
            fail(name + ": osmAG:from and osmAG:to must name two areas")
        if len(refs) < 2 or float(tags.get("areagraph:width", "nan")) <= 0:
            fail(name + ": at least two nodes and an areagraph:width")
        for ref in refs:
            for end in ends:
                if not any(ref in ring for ring in areas[end][1]):
                    fail("%s: node %s is not a node of %s" % (name, ref, end))
            shared += 1
    print("%d areas, %d passages, %d passage nodes shared" % (len(areas), len(passages), shared))


if __name__ == "__main__":
    main()
