#include "stages/import/import_stage.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <system_error>
#include <vector>

#include "common/error.h"
#include "common/input_file.h"
#include "stages/common/pipeline_options_check.h"
#include "stages/geometry/pool_tasks.h"
#include "stages/import/grey_image.h"
#include "stages/import/grid_map_decoder.h"
#include "store/digest.h"

namespace areagraph {
namespace {

namespace fs = std::filesystem;

bool IsYamlPath(const std::string& path) {
  const std::string extension = fs::path(path).extension().string();
  return extension == ".yaml" || extension == ".yml";
}

}  // namespace

std::string ImportSource::Digest() const {
  if (digest_memo.empty()) {
    Sha256 digest;
    digest.Update(image_bytes);
    digest.Update(yaml_bytes);
    digest_memo = digest.FinishHex();
  }
  return digest_memo;
}

ImportSource ReadImportSource(const std::string& path) {
  ImportSource source;
  source.given_path = path;
  if (IsYamlPath(path)) {
    source.yaml_path = path;
    source.yaml_bytes = ReadInputFile(path, "map YAML '" + path + "'");
    source.yaml = ParseMapYaml(source.yaml_bytes, path, /*image_required=*/true);
    source.image_path = source.yaml->image_path;
    source.image_bytes = ReadInputFile(
        source.image_path, "image '" + source.image_path + "' (named in '" + path + "')");
    return source;
  }
  source.image_path = path;
  source.image_bytes = ReadInputFile(path, "image '" + path + "'");
  // map_server keeps the metadata next to the image under the same stem.
  const std::string beside = fs::path(path).replace_extension(".yaml").string();
  std::error_code error;
  if (fs::is_regular_file(beside, error)) {
    source.yaml_path = beside;
    source.yaml_bytes = ReadInputFile(beside, "map YAML '" + beside + "'");
    // The image given on the command line wins over the YAML's `image` key.
    source.yaml = ParseMapYaml(source.yaml_bytes, beside, /*image_required=*/false);
  }
  return source;
}

std::string DefaultMapName(const std::string& path) { return fs::path(path).stem().string(); }

proto::GridMap ImportGridMap(const ImportSource& source, const proto::ImportOptions& options) {
  CheckImportOptions(options);
  const GreyToCell rule = source.yaml ? MapServerRule(*source.yaml) : GreyThresholdRule(options);
  // ag-run has the digest from the cache key; elsewhere it is found beside
  // the decode, which only reads the bytes too.
  cv::Mat grey;
  std::vector<std::function<void()>> tasks = {
      [&] { grey = DecodeGreyImage(source.image_bytes, source.image_path, options.max_pixels()); }};
  if (!source.HasDigest()) tasks.push_back([&] { source.Digest(); });
  RunTasks(tasks);  // rethrows a task's exception with its own type

  proto::GridMap grid;
  grid.set_format_version(kGridMapFormatVersion);
  proto::MapFrame* frame = grid.mutable_frame();
  frame->set_resolution_m(source.yaml ? source.yaml->resolution_m : options.resolution_m());
  frame->set_origin_x_m(source.yaml ? source.yaml->origin_x_m : 0.0);
  frame->set_origin_y_m(source.yaml ? source.yaml->origin_y_m : 0.0);
  frame->set_origin_yaw_rad(source.yaml ? source.yaml->origin_yaw_rad : 0.0);
  frame->set_width_px(grey.cols);
  frame->set_height_px(grey.rows);
  grid.set_cells(ClassifyCells(grey, rule));
  grid.set_source_path(source.given_path);
  grid.set_source_digest(source.Digest());
  return grid;
}

StageInputs ImportInputs(const ImportSource& source) {
  StageInputs inputs;
  inputs.digests = {source.Digest()};
  inputs.source_path = source.given_path;
  inputs.source_digest = inputs.digests[0];
  return inputs;
}

std::string ImportCacheKey(const ImportSource& source, const proto::ImportOptions& options) {
  return StageCacheKey(kImportStage, options, ImportInputs(source).digests);
}

}  // namespace areagraph
