#include "stages/common/artifact_types.h"

#include "proto/artifacts.pb.h"

namespace areagraph {

std::unique_ptr<google::protobuf::Message> NewArtifactMessage(const std::string& proto_type) {
  // Listed explicitly so that the linker keeps every artifact type.
  const google::protobuf::Message* prototypes[] = {
      &proto::GridMap::default_instance(),        &proto::CleanedMap::default_instance(),
      &proto::VoronoiDiagram::default_instance(), &proto::TopologyGraph::default_instance(),
      &proto::CutGraph::default_instance(),       &proto::AreaGraph::default_instance()};
  for (const google::protobuf::Message* prototype : prototypes) {
    if (prototype->GetTypeName() == proto_type) {
      return std::unique_ptr<google::protobuf::Message>(prototype->New());
    }
  }
  return nullptr;
}

}  // namespace areagraph
