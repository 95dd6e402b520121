#!/usr/bin/env python3
"""A minimal Area Graph subscriber in Python: prints what main.cc prints for
every graph that ag-run --publish or ag-live sends on LCM channel AREA_GRAPH.

Debian 12 packages LCM for C, C++, Java and Lua but not for Python, so this
script speaks LCM's UDP multicast protocol itself (the standard library's
socket and struct suffice) and decodes with the classes that `lcm-gen -p`
makes from proto/area_graph_t.lcm, which need nothing but struct:

    lcm-gen -p --ppath lcm_types proto/area_graph_t.lcm
    python3 area_graph_subscriber.py --types lcm_types --count 1

With LCM's own Python bindings (built from source) the same classes work with
lcm.LCM(url).subscribe("AREA_GRAPH", handler).
"""
import argparse
import os
import socket
import struct
import sys
import time
import urllib.parse

SHORT_MAGIC = 0x4C433032  # "LC02": the whole message in one datagram
FRAGMENT_MAGIC = 0x4C433033  # "LC03": one fragment of a larger message
KIND_NAMES = {0: "room", 1: "corridor", 2: "dead_end"}


def open_socket(url):
    """Joins the multicast group of an udpm:// URL; returns the socket."""
    parsed = urllib.parse.urlparse(url)
    if parsed.scheme != "udpm" or not parsed.hostname or not parsed.port:
        raise ValueError("only udpm://GROUP:PORT URLs are supported, not '%s'" % url)
    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM, socket.IPPROTO_UDP)
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    if hasattr(socket, "SO_REUSEPORT"):  # several subscribers on one host
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEPORT, 1)
    # Large graphs arrive as bursts of fragments; a small buffer drops them.
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 8 << 20)
    sock.bind(("", parsed.port))
    membership = struct.pack("4s4s", socket.inet_aton(parsed.hostname),
                             socket.inet_aton("0.0.0.0"))
    sock.setsockopt(socket.IPPROTO_IP, socket.IP_ADD_MEMBERSHIP, membership)
    return sock


class Reassembler:
    """Turns datagrams into (channel, payload) messages. Keeps one message in
    progress per sender: a new one replaces an incomplete one, whose lost
    fragments would never come."""

    def __init__(self):
        self.partial = {}  # sender -> [sequence number, channel, buffer, bytes left]

    def add(self, datagram, sender):
        magic, sequence = struct.unpack_from(">II", datagram)
        if magic == SHORT_MAGIC:
            end = datagram.index(b"\0", 8)
            return datagram[8:end].decode(), datagram[end + 1:]
        if magic != FRAGMENT_MAGIC:
            return None
        size, offset, number, _ = struct.unpack_from(">IIHH", datagram, 8)
        data_start = 20
        if number == 0:
            end = datagram.index(b"\0", 20)
            self.partial[sender] = [sequence, datagram[20:end].decode(), bytearray(size), size]
            data_start = end + 1
        entry = self.partial.get(sender)
        if entry is None or entry[0] != sequence:
            return None  # the first fragment of this message was lost
        data = datagram[data_start:]
        entry[2][offset:offset + len(data)] = data
        entry[3] -= len(data)
        if entry[3] > 0:
            return None
        del self.partial[sender]
        return entry[1], bytes(entry[2])


def print_graph(channel, graph):
    # Ids are stable: area 7 of this graph is area 7 of the map's next graph while it is the
    # same space. `version` counts the map's graphs.
    print("%s: map '%s', %d areas, %d passages (key %s, version %d, message %d, sent at %d us)" %
          (channel, graph.map_name, graph.num_areas, graph.num_passages, graph.artifact_key[:12],
           graph.version, graph.sequence, graph.utime))
    for area in graph.areas:
        print("  area %d: %s, %g m2, centroid (%g, %g), %d outline points, %d holes" %
              (area.id, KIND_NAMES.get(area.kind, "unknown"), area.area_m2, area.centroid_x,
               area.centroid_y, area.outer.num_points, area.num_holes))
    for passage in graph.passages:
        print("  passage %d: area %d <-> area %d at (%g, %g), %g m wide" %
              (passage.id, passage.area_a, passage.area_b, passage.x, passage.y,
               passage.width_m))
    sys.stdout.flush()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--url", default="udpm://239.255.76.67:7667?ttl=0",
                        help="LCM URL (udpm only; default: this host only)")
    parser.add_argument("--channel", default="AREA_GRAPH")
    parser.add_argument("--types", default=os.path.join(os.path.dirname(__file__), "lcm_types"),
                        help="folder that lcm-gen -p --ppath wrote areagraph_lcm into")
    parser.add_argument("--count", type=int, default=0,
                        help="exit after this many graphs (default: run until killed)")
    parser.add_argument("--timeout", type=float, default=0,
                        help="exit with 1 after this many seconds without enough graphs")
    args = parser.parse_args()
    sys.path.insert(0, args.types)
    try:
        from areagraph_lcm import area_graph_t
    except ImportError:
        sys.exit("area_graph_subscriber.py: no areagraph_lcm in '%s'; run "
                 "lcm-gen -p --ppath %s proto/area_graph_t.lcm" % (args.types, args.types))
    try:
        sock = open_socket(args.url)
    except (OSError, ValueError) as error:
        sys.exit("area_graph_subscriber.py: cannot listen on '%s': %s; udpm needs a multicast "
                 "route, e.g. 'sudo ip route add 224.0.0.0/4 dev lo'" % (args.url, error))
    print("area_graph_subscriber.py: listening on %s, channel %s" % (args.url, args.channel),
          file=sys.stderr, flush=True)
    deadline = time.monotonic() + args.timeout if args.timeout > 0 else None
    reassembler, received = Reassembler(), 0
    while args.count <= 0 or received < args.count:
        if deadline is not None:
            sock.settimeout(max(0.01, deadline - time.monotonic()))
        try:
            datagram, sender = sock.recvfrom(65536)
        except socket.timeout:
            sys.exit("area_graph_subscriber.py: %d of %d graphs within %g s" %
                     (received, args.count, args.timeout))
        message = reassembler.add(datagram, sender)
        if message is None or message[0] != args.channel:
            continue
        try:
            graph = area_graph_t.decode(message[1])
        except (ValueError, struct.error):
            print("area_graph_subscriber.py: skipped a message on %s that is not an area_graph_t"
                  % args.channel, file=sys.stderr)
            continue
        print_graph(message[0], graph)
        received += 1


if __name__ == "__main__":
    main()
