"""Checks a GeoJSON file from ag-export: unique feature ids, the top-level
members, coordinates of the promised kind, and shapely finds every polygon
valid.

Usage: check_geojson.py FILE --map NAME [--anchor LAT LON]
Prints "<areas> areas, <passages> passages, all polygons valid" and exits 0,
or prints the first broken rule and exits 1.
"""
import argparse
import json
import sys

from shapely.geometry import shape
from shapely.validation import explain_validity


def fail(message):
    print("check_geojson: " + message, file=sys.stderr)
    sys.exit(1)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("file")
    parser.add_argument("--map", required=True)
    parser.add_argument("--anchor", nargs=2, type=float)
    args = parser.parse_args()

    with open(args.file) as f:
        collection = json.load(f)
    if collection.get("type") != "FeatureCollection" or collection.get("name") != args.map:
        fail("a FeatureCollection named " + args.map)
    if collection.get("frame", {}).get("resolution_m", 0) <= 0:
        fail("the map frame as a top-level member")
    units = "degrees" if args.anchor else "metres"
    if collection.get("units") != units or "crs" in collection and args.anchor:
        fail("units must be %s (and WGS 84 files carry no crs member)" % units)
    if not args.anchor and "ENGCRS" not in collection["crs"]["properties"]["name"]:
        fail("a file in metres names its local CRS")

    features = collection["features"]
    ids = [feature["id"] for feature in features]
    if len(set(ids)) != len(ids):
        fail("feature ids must be unique")
    counts = {"area": 0, "passage": 0}
    for feature in features:
        layer = feature["properties"]["layer"]
        if feature["id"] != "%s/%d" % (layer, feature["properties"][layer + "_id"]):
            fail("feature id %s does not match its layer and number" % feature["id"])
        counts[layer] += 1
        geometry = shape(feature["geometry"])
        if layer == "area" and not geometry.is_valid:
            fail("%s is not a valid polygon: %s" % (feature["id"], explain_validity(geometry)))
        if args.anchor:
            lon, lat = geometry.centroid.x, geometry.centroid.y
            if abs(lat - args.anchor[0]) > 0.01 or abs(lon - args.anchor[1]) > 0.01:
                fail("%s lies more than 1 km from the anchor" % feature["id"])
    print("%d areas, %d passages, all polygons valid" % (counts["area"], counts["passage"]))


if __name__ == "__main__":
    main()
