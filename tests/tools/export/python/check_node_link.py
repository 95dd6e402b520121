"""Loads ag-export --format json with networkx in one line and prints what it
holds: "<name>: MultiGraph, <nodes> nodes, <edges> edges, <pairs> area pairs,
kinds <sorted kinds>". Exits 1 with a message if it is not an undirected
MultiGraph with polygons on its nodes and borders on its edges.
"""
import json
import sys

import networkx as nx


def main():
    with open(sys.argv[1]) as f:
        graph = nx.node_link_graph(json.load(f))
    if not graph.is_multigraph() or graph.is_directed():
        sys.exit("check_node_link: not an undirected MultiGraph")
    for area, data in graph.nodes(data=True):
        if len(data["polygon"]) < 3 or data["name"] != "area_%d" % area:
            sys.exit("check_node_link: area %d has no polygon or name" % area)
    for a, b, key, data in graph.edges(keys=True, data=True):
        if len(data["border"]) < 2 or data["id"] != key or data["width_m"] <= 0:
            sys.exit("check_node_link: passage %d lacks its border, id or width" % key)
    pairs = {frozenset((a, b)) for a, b in graph.edges()}
    kinds = sorted({kind for _, kind in graph.nodes(data="kind")})
    print("%s: %s, %d nodes, %d edges, %d area pairs, kinds %s" %
          (graph.graph["name"], type(graph).__name__, graph.number_of_nodes(),
           graph.number_of_edges(), len(pairs), " ".join(kinds)))


if __name__ == "__main__":
    main()
