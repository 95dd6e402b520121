#pragma once

#include <lcm/lcm-cpp.hpp>
#include <memory>
#include <string>

#include "proto/artifacts.pb.h"
#include "runner/live/lcm_connection.h"

namespace areagraph {

// Channel of finished Area Graphs (area_graph_t).
inline constexpr char kAreaGraphChannel[] = "AREA_GRAPH";
// Channel of live occupancy grids for ag-live (grid_map_t).
inline constexpr char kGridMapChannel[] = "MAP";

// Sends Area Graphs as area_graph_t on AREA_GRAPH, for ag-run --publish and
// ag-live. Traffic stays on the host (see HostLocalLcmUrl).
class AreaGraphPublisher {
 public:
  // Throws OptionsError for a URL that would leave the host, and Error with
  // the likely fix when LCM cannot start.
  explicit AreaGraphPublisher(const std::string& url = kDefaultLcmUrl);

  // Throws Error when LCM cannot send (for udpm: usually no multicast route).
  void Publish(const std::string& map_name, const std::string& cache_key,
               const proto::AreaGraph& graph);

  // The LCM instance, for subscribing on the same one: memq:// reaches only
  // subscribers of the instance that publishes.
  lcm::LCM& connection() { return *lcm_; }
  // The URL in use, with ttl=0 added where it was missing.
  const std::string& url() const { return url_; }

 private:
  std::string url_;
  std::unique_ptr<lcm::LCM> lcm_;
};

}  // namespace areagraph
