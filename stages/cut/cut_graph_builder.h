#pragma once

#include <functional>
#include <string>

#include "proto/artifacts.pb.h"
#include "proto/pipeline_options.pb.h"

namespace areagraph {

// ag-cut: room detection and edge cutting (the paper's G_A^1). The rooms are
// the regions of the obstacle sites' Delaunay triangulation where a disk of
// diameter W fits (alpha shape with alpha = (W / 2)^2, see RoomWidthM) and
// that lie inside the Topology Graph's boundary. Every edge is cut where it
// passes from one room to another or out of all rooms (see PlanEdgeCuts);
// each cut adds a VERTEX_PASSAGE vertex and a PassagePoint. Rooms smaller
// than the disk of diameter W are slivers of a corridor about W wide and
// count as no room; of the others, only those that some edge runs through
// are kept, renumbered from 0. Throws OptionsError for a bad W and
// InputError for a corrupt input. `owned`, when given, is `topology` itself,
// which the caller gives up: its edges are taken one by one (an edge that
// stays one piece moves into the Cut Graph, absorbed polygons move to their
// pieces) and each is freed once read, so the copies take the memory it frees.
// `between_steps`, when given, is called where cut's working set is about to
// grow from fresh memory: first thing, and once the room-width estimate's
// scratch is freed (a program may give freed memory back there).
proto::CutGraph BuildCutGraph(const proto::TopologyGraph& topology, const proto::CleanedMap& map,
                              const proto::CutOptions& options,
                              proto::TopologyGraph* owned = nullptr,
                              const std::function<void()>& between_steps = nullptr);

}  // namespace areagraph
