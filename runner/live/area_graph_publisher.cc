#include "runner/live/area_graph_publisher.h"

#include <chrono>

#include "common/error.h"
#include "runner/live/lcm_connection.h"
#include "runner/live/lcm_conversion.h"

namespace areagraph {
namespace {

int64_t MicrosecondsNow() {
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace

AreaGraphPublisher::AreaGraphPublisher(const std::string& url)
    : url_(HostLocalLcmUrl(url)), lcm_(OpenLcm(url_)) {}

template <typename Message>
void AreaGraphPublisher::Send(const char* channel, const std::string& map_name,
                              const Message& message) {
  if (lcm_->publish(channel, &message) != 0) {
    std::string text = "cannot publish the Area Graph of map '" + map_name + "' on " + channel +
                       " at '" + url_ + "'";
    if (url_.rfind("udpm://", 0) == 0) text += "; " + MulticastRouteHint();
    throw Error(text);
  }
}

void AreaGraphPublisher::Publish(const std::string& map_name, const std::string& cache_key,
                                 const proto::AreaGraph& graph, int64_t map_utime) {
  areagraph_lcm::area_graph_t message = ToLcmAreaGraph(map_name, cache_key, graph);
  message.utime = MicrosecondsNow();
  message.sequence = graphs_sent_;
  message.map_utime = map_utime;
  Send(kAreaGraphChannel, map_name, message);
  ++graphs_sent_;
}

void AreaGraphPublisher::PublishDiff(const std::string& map_name, const std::string& cache_key,
                                     const proto::AreaGraphDiff& diff,
                                     const proto::AreaGraph& after, int64_t map_utime) {
  areagraph_lcm::area_graph_diff_t message = ToLcmAreaGraphDiff(map_name, cache_key, diff, after);
  message.utime = MicrosecondsNow();
  message.sequence = diffs_sent_;
  message.map_utime = map_utime;
  Send(kAreaGraphDiffChannel, map_name, message);
  ++diffs_sent_;
}

}  // namespace areagraph
