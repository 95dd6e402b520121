#include "tools/listen/area_graph_listener.h"

#include <climits>
#include <sstream>

#include "common/error.h"
#include "common/text.h"
#include "runner/live/area_graph_publisher.h"
#include "runner/live/lcm_connection.h"
#include "runner/live/lcm_conversion.h"
#include "stages/pipeline/stage.h"
#include "store/cache_key.h"

namespace areagraph {

std::string DescribeAreaGraph(const areagraph_lcm::area_graph_t& message) {
  std::ostringstream line;
  line << "map " << message.map_name << ": " << message.num_areas << " areas, "
       << message.num_passages << " passages, key " << ShortKey(message.artifact_key)
       << ", version " << message.version;
  return line.str();
}

std::string DescribeAreaGraphDiff(const areagraph_lcm::area_graph_diff_t& message) {
  std::ostringstream line;
  line << "diff " << message.map_name << ": version " << message.predecessor_version << " -> "
       << message.version << ", areas +" << message.num_added_areas << " -"
       << message.num_removed_areas << " ~" << message.num_changed_areas << " ="
       << message.unchanged_areas << ", passages +" << message.num_added_passages << " -"
       << message.num_removed_passages << " ~" << message.num_changed_passages << " ="
       << message.unchanged_passages;
  return line.str();
}

std::string ReceivedAreaGraphKey(const std::string& published_key) {
  return ComputeCacheKey("received-over-lcm", 1, "", {published_key});
}

bool StoreReceivedAreaGraph(ArtifactStore& store, const areagraph_lcm::area_graph_t& message) {
  const proto::AreaGraph graph = AreaGraphFromLcm(message);
  if (message.artifact_key.empty() || message.artifact_key.find('\n') != std::string::npos) {
    throw InputError("area_graph_t for map '" + message.map_name + "' has no usable artifact key");
  }
  const std::string key = ReceivedAreaGraphKey(message.artifact_key);
  if (store.HasArtifact(message.map_name, key)) {
    store.UpdateHead(message.map_name, key);
    return false;
  }
  NewArtifact artifact;
  artifact.map_name = message.map_name;
  artifact.stage = kMergeStage.name;
  artifact.cache_key = key;
  // The publisher's key is not an artifact of this store, so it is kept in
  // the options text rather than as an input key (which ag-store verify checks).
  artifact.options_text = "received_over_lcm { published_key: \"" + message.artifact_key + "\" }";
  artifact.stage_version = 0;
  artifact.proto_type = graph.GetTypeName();
  artifact.payload = graph.SerializeAsString();
  store.WriteArtifact(artifact);
  return true;
}

AreaGraphListener::AreaGraphListener(lcm::LCM& lcm, std::string url, ArtifactStore* store,
                                     std::ostream& out, std::ostream& log, bool diffs)
    : lcm_(lcm), url_(std::move(url)), store_(store), out_(out), log_(log) {
  subscription_ = lcm_.subscribe(kAreaGraphChannel, &AreaGraphListener::OnMessage, this);
  if (diffs) {
    diff_subscription_ =
        lcm_.subscribe(kAreaGraphDiffChannel, &AreaGraphListener::OnDiffMessage, this);
  }
  StartReceiving(lcm_, url_);
}

AreaGraphListener::~AreaGraphListener() {
  lcm_.unsubscribe(subscription_);
  if (diff_subscription_ != nullptr) lcm_.unsubscribe(diff_subscription_);
}

void AreaGraphListener::OnDiffMessage(const lcm::ReceiveBuffer* buffer,
                                      const std::string& channel) {
  try {
    if (buffer->data_size > static_cast<uint32_t>(INT_MAX)) throw InputError("message too big");
    const areagraph_lcm::area_graph_diff_t message =
        DecodeAreaGraphDiffMessage(buffer->data, static_cast<int>(buffer->data_size));
    ++diffs_received_;
    out_ << DescribeAreaGraphDiff(message) << std::endl;
  } catch (const std::exception& error) {
    ++messages_rejected_;
    log_ << "ag-listen: skipped a malformed message on " << channel << " (" << buffer->data_size
         << " bytes): " << error.what() << std::endl;
  }
}

bool AreaGraphListener::Listen(int timeout_ms) { return HandleOneMessage(lcm_, timeout_ms, url_); }

void AreaGraphListener::OnMessage(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
  areagraph_lcm::area_graph_t message;
  try {
    if (buffer->data_size > static_cast<uint32_t>(INT_MAX)) throw InputError("message too big");
    message = DecodeAreaGraphMessage(buffer->data, static_cast<int>(buffer->data_size));
    // Checked even without a store, so that what is printed is a valid graph.
    AreaGraphFromLcm(message);
  } catch (const std::exception& error) {
    ++messages_rejected_;
    log_ << "ag-listen: skipped a malformed message on " << channel << " (" << buffer->data_size
         << " bytes): " << error.what() << std::endl;
    return;
  }
  ++graphs_received_;
  std::string stored;
  if (store_ != nullptr) {
    try {
      stored = StoreReceivedAreaGraph(*store_, message) ? ", stored" : ", already stored";
    } catch (const std::exception& error) {
      stored = ", not stored";
      log_ << "ag-listen: cannot store the graph of map '" << message.map_name
           << "': " << error.what() << std::endl;
    }
  }
  out_ << DescribeAreaGraph(message) << stored << std::endl;
}

}  // namespace areagraph
