#pragma once

#include <memory>
#include <string>

#include "proto/artifacts.pb.h"
#include "tools/route/area_router.h"
#include "tools/route/free_space.h"

namespace areagraph::python {

// An Area Graph held for Python, with its free space and router built on
// first use (the router's set-up costs far more than one query).
class GraphHandle {
 public:
  GraphHandle(proto::AreaGraph graph, std::string map_name)
      : graph_(std::move(graph)), map_name_(std::move(map_name)) {}

  const proto::AreaGraph& graph() const { return graph_; }
  const std::string& map_name() const { return map_name_; }
  const FreeSpace& free_space() {
    if (!space_) space_ = std::make_unique<FreeSpace>(graph_);
    return *space_;
  }
  const AreaRouter& router() {
    if (!router_) router_ = std::make_unique<AreaRouter>(graph_);
    return *router_;
  }

 private:
  proto::AreaGraph graph_;
  std::string map_name_;
  std::unique_ptr<FreeSpace> space_;
  std::unique_ptr<AreaRouter> router_;
};

}  // namespace areagraph::python
