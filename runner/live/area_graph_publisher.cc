#include "runner/live/area_graph_publisher.h"

#include "common/error.h"
#include "runner/live/lcm_connection.h"
#include "runner/live/lcm_conversion.h"

namespace areagraph {

AreaGraphPublisher::AreaGraphPublisher(const std::string& url)
    : url_(HostLocalLcmUrl(url)), lcm_(OpenLcm(url_)) {}

void AreaGraphPublisher::Publish(const std::string& map_name, const std::string& cache_key,
                                 const proto::AreaGraph& graph) {
  const areagraph_lcm::area_graph_t message = ToLcmAreaGraph(map_name, cache_key, graph);
  if (lcm_->publish(kAreaGraphChannel, &message) != 0) {
    std::string text = "cannot publish the Area Graph of map '" + map_name + "' on " +
                       kAreaGraphChannel + " at '" + url_ + "'";
    if (url_.rfind("udpm://", 0) == 0) text += "; " + MulticastRouteHint();
    throw Error(text);
  }
}

}  // namespace areagraph
