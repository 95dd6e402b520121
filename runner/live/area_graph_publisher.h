#pragma once

#include <lcm/lcm-cpp.hpp>
#include <memory>
#include <string>

#include "proto/area_graph_diff.pb.h"
#include "proto/artifacts.pb.h"
#include "runner/live/lcm_connection.h"

namespace areagraph {

// Channel of finished Area Graphs (area_graph_t).
inline constexpr char kAreaGraphChannel[] = "AREA_GRAPH";
// Channel of what changed from one version of a map's Area Graph to the next
// (area_graph_diff_t, ag-live --diffs).
inline constexpr char kAreaGraphDiffChannel[] = "AREA_GRAPH_DIFF";
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
  // The message gets the time now as utime, the next sequence number of
  // AREA_GRAPH, and `map_utime` (the grid's utime, 0 for a file).
  void Publish(const std::string& map_name, const std::string& cache_key,
               const proto::AreaGraph& graph, int64_t map_utime = 0);

  // Sends `diff` (from the previous version to `after`, whose key is
  // `cache_key`) on AREA_GRAPH_DIFF, numbered on that channel.
  void PublishDiff(const std::string& map_name, const std::string& cache_key,
                   const proto::AreaGraphDiff& diff, const proto::AreaGraph& after,
                   int64_t map_utime = 0);

  // The LCM instance, for subscribing on the same one: memq:// reaches only
  // subscribers of the instance that publishes.
  lcm::LCM& connection() { return *lcm_; }
  // The URL in use, with ttl=0 added where it was missing.
  const std::string& url() const { return url_; }

 private:
  // Sends `message` on `channel`; throws Error saying why it could not.
  template <typename Message>
  void Send(const char* channel, const std::string& map_name, const Message& message);

  std::string url_;
  std::unique_ptr<lcm::LCM> lcm_;
  int64_t graphs_sent_ = 0;
  int64_t diffs_sent_ = 0;
};

}  // namespace areagraph
