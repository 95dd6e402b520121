#pragma once

#include <lcm/lcm-cpp.hpp>
#include <ostream>
#include <string>

#include "areagraph_lcm/area_graph_diff_t.hpp"
#include "areagraph_lcm/area_graph_t.hpp"
#include "store/artifact_store.h"

namespace areagraph {

// The line ag-listen prints for a graph: map, areas, passages, the first 12
// characters of its key (as ag-inspect shows keys) and its version.
std::string DescribeAreaGraph(const areagraph_lcm::area_graph_t& message);

// The line ag-listen --diffs prints for a diff: map, versions, and how many
// areas and passages were added (+), removed (-), changed (~) and kept (=).
std::string DescribeAreaGraphDiff(const areagraph_lcm::area_graph_diff_t& message);

// The cache key under which a received graph is stored: derived from the
// publisher's key, so receiving the same graph twice stores it once, but
// never equal to it. A received graph lacks what area_graph_t leaves out
// (topology edge ids, exact pixel polygons), so it must not pass for the
// publisher's artifact if the stores are ever merged, nor be taken as a
// cache hit by a pipeline run in the receiving store.
std::string ReceivedAreaGraphKey(const std::string& published_key);

// Stores a received graph as its map's merge artifact and head: the map's
// Area Graph, which ag-export and ag-render then use. Its input key is the
// publisher's key, its stage version 0 and its options empty: this store
// does not know how it was made. Returns false when the same graph was
// already stored (only the head moves). Throws InputError for an
// inconsistent graph (see AreaGraphFromLcm) and StoreError.
bool StoreReceivedAreaGraph(ArtifactStore& store, const areagraph_lcm::area_graph_t& message);

// ag-listen's work: prints every area_graph_t received on AREA_GRAPH, and
// saves it when given a store. Malformed messages are reported and skipped.
class AreaGraphListener {
 public:
  // Subscribes on `lcm` (whose URL `url` names it in errors), to
  // AREA_GRAPH_DIFF too with `diffs`, and starts receiving; `store` may be null.
  AreaGraphListener(lcm::LCM& lcm, std::string url, ArtifactStore* store, std::ostream& out,
                    std::ostream& log, bool diffs = false);
  ~AreaGraphListener();
  AreaGraphListener(const AreaGraphListener&) = delete;
  AreaGraphListener& operator=(const AreaGraphListener&) = delete;

  // Waits up to `timeout_ms` for one message; true when one arrived.
  bool Listen(int timeout_ms);

  int graphs_received() const { return graphs_received_; }
  int diffs_received() const { return diffs_received_; }
  int messages_rejected() const { return messages_rejected_; }

 private:
  void OnMessage(const lcm::ReceiveBuffer* buffer, const std::string& channel);
  void OnDiffMessage(const lcm::ReceiveBuffer* buffer, const std::string& channel);

  lcm::LCM& lcm_;
  std::string url_;
  ArtifactStore* store_;
  std::ostream& out_;
  std::ostream& log_;
  lcm::Subscription* subscription_ = nullptr;
  lcm::Subscription* diff_subscription_ = nullptr;
  int graphs_received_ = 0;
  int diffs_received_ = 0;
  int messages_rejected_ = 0;
};

}  // namespace areagraph
