// areagraph._core.segment_file / segment_grid: the pipeline that ag-run runs
// (import, then every stage with the same options and defaults), on a private
// in-memory store.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <sstream>
#include <utility>

#include "common/error.h"
#include "python/module/bindings.h"
#include "python/module/graph_handle.h"
#include "runner/live/lcm_conversion.h"
#include "runner/live/live_map_server.h"
#include "stages/common/command_line.h"
#include "stages/common/pipeline_options_check.h"
#include "stages/import/import_stage.h"
#include "stages/import/map_yaml.h"
#include "stages/pipeline/map_pipeline.h"
#include "stages/pipeline/stage.h"
#include "stages/pipeline/stage_table.h"

namespace areagraph::python {
namespace {

namespace py = pybind11;
using Origin = std::pair<double, double>;

proto::PipelineOptions LoadOptions(const std::string& options_file,
                                   const std::vector<std::string>& overrides) {
  StageCommandLine flags;
  flags.options_file = options_file;
  flags.overrides = overrides;
  return LoadPipelineOptions(flags);
}

void CheckOrigin(const Origin& origin) {
  const std::string problem = OriginProblem(origin.first, origin.second, 0);
  if (!problem.empty()) throw OptionsError("origin: " + problem);
}

// Imports `grid` into a private store and runs every stage after import.
std::shared_ptr<GraphHandle> RunPipeline(const std::string& map_name, const proto::GridMap& grid,
                                         const StageInputs& inputs,
                                         const proto::PipelineOptions& options) {
  const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(":memory:");
  RunCachedStage(*store, map_name, StageOf(kImportStage), options, inputs,
                 [&grid] { return std::make_unique<proto::GridMap>(grid); });
  RunMapPipeline(*store, map_name, options, /*force=*/false,
                 [](const StageInfo&, const StageRun&) {});
  return std::make_shared<GraphHandle>(
      ReadHeadArtifact<proto::AreaGraph>(*store, map_name, FinalStage()), map_name);
}

std::shared_ptr<GraphHandle> SegmentFile(const std::string& path,
                                         std::optional<double> resolution_m,
                                         std::optional<Origin> origin,
                                         const std::string& options_file,
                                         const std::vector<std::string>& overrides) {
  py::gil_scoped_release unlocked;
  proto::PipelineOptions options = LoadOptions(options_file, overrides);
  if (resolution_m) {
    CheckResolution(*resolution_m, "resolution", /*is_option=*/true);
    options.mutable_import()->set_resolution_m(*resolution_m);
  }
  if (origin) CheckOrigin(*origin);
  const ImportSource source = ReadImportSource(path);
  if (source.yaml && resolution_m && *resolution_m != source.yaml->resolution_m) {
    std::ostringstream message;
    message << "resolution " << *resolution_m << " contradicts resolution "
            << source.yaml->resolution_m << " in '" << *source.yaml_path
            << "'; edit the YAML or leave resolution out";
    throw OptionsError(message.str());
  }
  if (source.yaml && origin &&
      (origin->first != source.yaml->origin_x_m || origin->second != source.yaml->origin_y_m)) {
    throw OptionsError("origin contradicts the origin in '" + *source.yaml_path +
                       "'; edit the YAML or leave origin out");
  }
  const std::string map_name = DefaultMapName(path);
  if (map_name.empty()) throw InputError("cannot name the map after '" + path + "'");
  proto::GridMap grid = ImportGridMap(source, options.import());
  StageInputs inputs = ImportInputs(source);
  if (origin && !source.yaml) {
    grid.mutable_frame()->set_origin_x_m(origin->first);
    grid.mutable_frame()->set_origin_y_m(origin->second);
    inputs.digests.push_back(LiveGridDigest(grid));  // the origin changes every metre
  }
  return RunPipeline(map_name, grid, inputs, options);
}

std::shared_ptr<GraphHandle> SegmentLcmGrid(const areagraph_lcm::grid_map_t& message,
                                            const std::string& options_file,
                                            const std::vector<std::string>& overrides) {
  py::gil_scoped_release unlocked;
  const proto::PipelineOptions options = LoadOptions(options_file, overrides);
  CheckResolution(message.resolution_m, "resolution", /*is_option=*/true);
  CheckOrigin({message.origin_x_m, message.origin_y_m});
  const proto::GridMap grid = GridMapFromLcm(message, options.import().max_pixels());
  StageInputs inputs;
  inputs.digests = {LiveGridDigest(grid)};
  return RunPipeline(message.name, grid, inputs, options);
}

// A 2-D int8 or uint8 array in ROS's OccupancyGrid convention: row 0 at the
// origin (the bottom), 0..100 percent occupied, -1 (255) unknown.
std::shared_ptr<GraphHandle> SegmentGrid(const py::array& cells, double resolution_m,
                                         const Origin& origin, const std::string& options_file,
                                         const std::vector<std::string>& overrides,
                                         const std::string& map_name) {
  if (cells.ndim() != 2) {
    throw InputError("the grid must be a 2-D array (rows, columns); it has " +
                     std::to_string(cells.ndim()) + " dimensions");
  }
  if (!cells.dtype().is(py::dtype::of<uint8_t>()) && !cells.dtype().is(py::dtype::of<int8_t>())) {
    throw InputError(
        "the grid must hold uint8 or int8 values (ROS: 0..100, -1 or 255 unknown); "
        "it holds " +
        std::string(py::str(cells.dtype())));
  }
  const auto contiguous = py::array::ensure(cells, py::array::c_style);
  const auto* data = static_cast<const int8_t*>(contiguous.data());
  areagraph_lcm::grid_map_t message;
  message.cells.assign(data, data + contiguous.size());
  if (cells.dtype().is(py::dtype::of<uint8_t>())) {
    for (size_t i = 0; i < message.cells.size(); ++i) {
      const int value = static_cast<uint8_t>(message.cells[i]);
      if (value > 100 && value != 255) {
        throw InputError("grid cell (row " + std::to_string(i / cells.shape(1)) + ", column " +
                         std::to_string(i % cells.shape(1)) + ") holds " + std::to_string(value) +
                         "; valid are 0..100 (percent occupied) and 255 (unknown)");
      }
    }
  }
  message.name = map_name;
  message.resolution_m = resolution_m;
  message.origin_x_m = origin.first;
  message.origin_y_m = origin.second;
  message.origin_yaw_rad = 0;
  message.height = static_cast<int32_t>(cells.shape(0));
  message.width = static_cast<int32_t>(cells.shape(1));
  message.num_cells = static_cast<int32_t>(message.cells.size());
  return SegmentLcmGrid(message, options_file, overrides);
}

}  // namespace

void AddSegment(py::module_& module) {
  module.def("segment_file", &SegmentFile, py::arg("path"), py::arg("resolution_m"),
             py::arg("origin"), py::arg("options_file"), py::arg("overrides"));
  module.def("segment_grid", &SegmentGrid, py::arg("cells"), py::arg("resolution_m"),
             py::arg("origin"), py::arg("options_file"), py::arg("overrides"), py::arg("map_name"));
}

}  // namespace areagraph::python
