// areagraph._core.StoreReader: a store opened read-only, giving graphs,
// artifacts as serialized protobuf, and history as plain values.
#include <google/protobuf/descriptor.h>
#include <google/protobuf/descriptor.pb.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <functional>
#include <memory>
#include <set>
#include <string>

#include "common/error.h"
#include "python/module/bindings.h"
#include "python/module/graph_handle.h"
#include "stages/pipeline/stage.h"
#include "stages/pipeline/stage_table.h"
#include "store/artifact_store.h"
#include "tools/route/stored_graph.h"

namespace areagraph::python {
namespace {

namespace py = pybind11;

class StoreReader {
 public:
  explicit StoreReader(const std::string& path)
      : store_(OpenArtifactStore(path, StoreMode::kReadOnly)) {}

  std::vector<std::string> Maps() {
    std::vector<std::string> names;
    for (const MapRecord& map : Open().ReadAllMaps()) names.push_back(map.name);
    return names;
  }

  std::shared_ptr<GraphHandle> AreaGraph(const std::string& map_name, const std::string& version) {
    return std::make_shared<GraphHandle>(ReadStoredAreaGraph(Open(), map_name, version), map_name);
  }

  // (message type, serialized message) of the head artifact of (map, stage).
  py::tuple Artifact(const std::string& map_name, const std::string& stage_name) {
    const StageDefinition& stage = FindStage(stage_name);
    if (!Open().ReadMap(map_name)) throw InputError("map '" + map_name + "' is not in the store");
    const MessagePtr message = NewArtifactMessage(stage.proto_type);
    ParseHeadArtifact(Open(), map_name, stage.info, message.get(), nullptr);
    return py::make_tuple(message->GetTypeName(), py::bytes(message->SerializeAsString()));
  }

  // One tuple per version, oldest first: (number, key, predecessor key,
  // created at, stored, is head).
  py::list History(const std::string& map_name) {
    if (!Open().ReadMap(map_name)) throw InputError("map '" + map_name + "' is not in the store");
    py::list versions;
    for (const VersionRecord& version : Open().ReadVersions(map_name)) {
      versions.append(py::make_tuple(version.number, version.cache_key, version.predecessor_key,
                                     version.created_at, version.stored, version.is_head));
    }
    return versions;
  }

  void Close() { store_.reset(); }

 private:
  std::unique_ptr<ArtifactStore> store_;

  ArtifactStore& Open() {
    if (!store_) throw StoreError("the store is closed");
    return *store_;
  }
};

// Every .proto file of the artifact types, dependencies first, as a
// serialized FileDescriptorSet: Python builds its message classes from it.
py::bytes DescriptorSet() {
  google::protobuf::FileDescriptorSet set;
  std::set<std::string> added;
  std::function<void(const google::protobuf::FileDescriptor*)> add =
      [&](const google::protobuf::FileDescriptor* file) {
        if (!added.insert(file->name()).second) return;
        for (int i = 0; i < file->dependency_count(); ++i) add(file->dependency(i));
        file->CopyTo(set.add_file());
      };
  for (const StageDefinition& stage : StageTable()) add(stage.prototype->GetDescriptor()->file());
  return py::bytes(set.SerializeAsString());
}

}  // namespace

void AddStore(py::module_& module) {
  py::class_<StoreReader>(module, "StoreReader", "A store opened read-only.")
      .def(py::init<const std::string&>(), py::arg("path"))
      .def("maps", &StoreReader::Maps)
      .def("area_graph", &StoreReader::AreaGraph, py::arg("map_name"), py::arg("version"))
      .def("artifact", &StoreReader::Artifact, py::arg("map_name"), py::arg("stage"))
      .def("history", &StoreReader::History, py::arg("map_name"))
      .def("close", &StoreReader::Close);
  module.def("descriptor_set", &DescriptorSet);
  module.def("stage_names", [] {
    std::vector<std::string> names;
    for (const StageDefinition& stage : StageTable()) names.push_back(stage.info.name);
    return names;
  });
}

}  // namespace areagraph::python
