#!/usr/bin/env python3
"""Prints the Area Graph of one map of a store, as networkx sees it, through the package
areagraph (bash tools/install-python.sh installs it):

    python3 examples/python/show_area_graph.py --store areagraph.db --map lab_a
"""

import argparse
import json
import sys

import networkx

import areagraph


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--store", default="areagraph.db", help="SQLite store")
    parser.add_argument("--map", required=True, help="map name")
    parser.add_argument("--json", action="store_true",
                        help="print networkx's node-link JSON instead of a summary")
    args = parser.parse_args()
    try:
        with areagraph.Store(args.store) as store:
            graph = store.area_graph(args.map).to_networkx()
    except areagraph.Error as error:
        sys.exit(f"show_area_graph: {error}")
    if args.json:
        print(json.dumps(networkx.node_link_data(graph)))
        return
    print(f"{args.map}: {graph.number_of_nodes()} areas, {graph.number_of_edges()} passages, "
          f"{networkx.number_connected_components(graph)} connected part(s)")
    for node, data in sorted(graph.nodes(data=True)):
        print(f"  area {node}: {data['kind']}, {data['area_m2']:.1f} m2, "
              f"neighbours {sorted(set(graph.neighbors(node)))}")


if __name__ == "__main__":
    main()
