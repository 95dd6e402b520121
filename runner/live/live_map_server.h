#pragma once

#include <chrono>
#include <cstdint>
#include <lcm/lcm-cpp.hpp>
#include <map>
#include <ostream>
#include <string>

#include "proto/artifacts.pb.h"
#include "proto/pipeline_options.pb.h"
#include "runner/common/map_run.h"
#include "runner/live/area_graph_publisher.h"
#include "store/artifact_store.h"

namespace areagraph {

// The input digest of a live map's import artifact: SHA-256 of its frame and
// cells, so that the same grid sent again (even with a new utime) is a cache
// hit and costs nothing.
std::string LiveGridDigest(const proto::GridMap& grid);

// ag-live's work: grids arriving on MAP are stored as their map's import
// artifact, run through clean..merge with the cache, and the Area Graph is
// published on AREA_GRAPH. Bad messages and failing maps are reported on
// `log` and skipped; the server keeps serving.
class LiveMapServer {
 public:
  // Subscribes to MAP on `publisher`'s LCM instance and starts receiving.
  // `out` gets one line per map handled, `log` one line per problem.
  LiveMapServer(ArtifactStore& store, AreaGraphPublisher& publisher, proto::PipelineOptions options,
                std::ostream& out, std::ostream& log);
  ~LiveMapServer();
  LiveMapServer(const LiveMapServer&) = delete;
  LiveMapServer& operator=(const LiveMapServer&) = delete;

  // Waits up to `timeout_ms` for grids, takes in all that are queued, then
  // handles the newest grid of each map. Returns how many maps it handled.
  int Serve(int timeout_ms);

  // Also publish on AREA_GRAPH_DIFF what changed from each map's previous
  // version (off by default).
  void set_publish_diffs(bool publish_diffs) { publish_diffs_ = publish_diffs; }

  int maps_handled() const { return maps_handled_; }
  int messages_rejected() const { return messages_rejected_; }
  int maps_failed() const { return maps_failed_; }

 private:
  // A grid waiting to be handled, with when and with what utime it came.
  struct PendingGrid {
    proto::GridMap grid;
    int64_t utime = 0;
    std::chrono::steady_clock::time_point received;
  };

  void OnGridMessage(const lcm::ReceiveBuffer* buffer, const std::string& channel);
  void HandleMap(const std::string& map_name, PendingGrid pending);
  // Publishes the graph, preceded by its diff when asked for and it is new.
  void PublishGraph(const std::string& map_name, const std::string& key,
                    const proto::AreaGraph& graph, int64_t map_utime);

  ArtifactStore& store_;
  FailureLog failures_;
  AreaGraphPublisher& publisher_;
  proto::PipelineOptions options_;
  std::ostream& out_;
  std::ostream& log_;
  lcm::Subscription* subscription_ = nullptr;
  // Grids received but not yet handled, newest per map name.
  std::map<std::string, PendingGrid> pending_;
  bool publish_diffs_ = false;
  // The key of the graph last published per map, so a repeat sends no diff.
  std::map<std::string, std::string> last_published_;
  int maps_handled_ = 0;
  int messages_rejected_ = 0;
  int maps_failed_ = 0;
};

}  // namespace areagraph
