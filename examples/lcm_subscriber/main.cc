// A minimal Area Graph subscriber: prints the areas and passages of every
// graph that ag-run --publish or ag-live sends on LCM channel AREA_GRAPH.
// Copy this folder into your project; see README.md.
//
// Usage: area_graph_subscriber [URL [COUNT]]
//   URL    LCM URL (default udpm://239.255.76.67:7667?ttl=0: this host only)
//   COUNT  exit after this many graphs (default: run until killed)
#include <cstdlib>
#include <iostream>
#include <lcm/lcm-cpp.hpp>
#include <string>

#include "areagraph_lcm/area_graph_t.hpp"

namespace {

const char* KindName(int8_t kind) {
  switch (kind) {
    case areagraph_lcm::area_t::ROOM:
      return "room";
    case areagraph_lcm::area_t::CORRIDOR:
      return "corridor";
    case areagraph_lcm::area_t::DEAD_END:
      return "dead_end";
    default:
      return "unknown";
  }
}

class AreaGraphPrinter {
 public:
  void OnAreaGraph(const lcm::ReceiveBuffer*, const std::string& channel,
                   const areagraph_lcm::area_graph_t* graph) {
    ++received_;
    // Ids are stable: area 7 of this graph is area 7 of the map's next graph
    // while it is the same space. `version` counts the map's graphs.
    std::cout << channel << ": map '" << graph->map_name << "', " << graph->num_areas << " areas, "
              << graph->num_passages << " passages (key " << graph->artifact_key.substr(0, 12)
              << ", version " << graph->version << ", message " << graph->sequence << ", sent at "
              << graph->utime << " us)\n";
    for (const areagraph_lcm::area_t& area : graph->areas) {
      std::cout << "  area " << area.id << ": " << KindName(area.kind) << ", " << area.area_m2
                << " m2, centroid (" << area.centroid_x << ", " << area.centroid_y << "), "
                << area.outer.num_points << " outline points, " << area.num_holes << " holes\n";
    }
    for (const areagraph_lcm::passage_t& passage : graph->passages) {
      std::cout << "  passage " << passage.id << ": area " << passage.area_a << " <-> area "
                << passage.area_b << " at (" << passage.x << ", " << passage.y << "), "
                << passage.width_m << " m wide\n";
    }
    std::cout.flush();
  }
  int received() const { return received_; }

 private:
  int received_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  // Keep ttl=0 on udpm: with a higher ttl the graphs would leave this host.
  const std::string url = argc > 1 ? argv[1] : "udpm://239.255.76.67:7667?ttl=0";
  const int count = argc > 2 ? std::atoi(argv[2]) : 0;
  lcm::LCM lcm(url);
  if (!lcm.good()) {
    std::cerr << "area_graph_subscriber: cannot open LCM at '" << url
              << "'; udpm needs a multicast route, e.g. 'sudo ip route add 224.0.0.0/4 dev lo'\n";
    return 1;
  }
  AreaGraphPrinter printer;
  lcm.subscribe("AREA_GRAPH", &AreaGraphPrinter::OnAreaGraph, &printer);
  std::cerr << "area_graph_subscriber: listening on " << url << ", channel AREA_GRAPH\n";
  while (count <= 0 || printer.received() < count) {
    if (lcm.handle() != 0) {
      std::cerr << "area_graph_subscriber: LCM stopped receiving\n";
      return 1;
    }
  }
  return 0;
}
