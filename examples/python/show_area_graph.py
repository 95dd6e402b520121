#!/usr/bin/env python3
"""Prints the Area Graph of one map of a store, as networkx sees it.

    python3 examples/python/show_area_graph.py --store areagraph.db --map lab_a
"""

import argparse
import json
import os
import sys

import networkx

from areagraph_store import AreagraphStore, to_networkx

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_DESCRIPTORS = os.path.join(HERE, "..", "..", "build", "python",
                                   "areagraph_descriptors.pb")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--store", default="areagraph.db", help="SQLite store")
    parser.add_argument("--map", required=True, help="map name")
    parser.add_argument("--descriptors", default=DEFAULT_DESCRIPTORS,
                        help="descriptor set the build writes (default: %(default)s)")
    parser.add_argument("--json", action="store_true",
                        help="print networkx's node-link JSON instead of a summary")
    args = parser.parse_args()
    try:
        store = AreagraphStore(args.store, args.descriptors)
        graph = to_networkx(store.area_graph(args.map))
    except (OSError, LookupError, ValueError) as error:
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
