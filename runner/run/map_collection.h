#pragma once

#include <string>
#include <vector>

#include "proto/pipeline_options.pb.h"

namespace areagraph {

// One map of a collection: where it is, what it is called in the store, and
// the per-map options a manifest gave it.
struct MapEntry {
  std::string name;
  std::string path;
  // "stage.field=value" assignments from manifest columns, applied after the
  // run's own options.
  std::vector<std::string> overrides;
  // Where the entry came from, for messages: a file, or "manifest.csv:7".
  std::string origin;
};

// The file extensions ag-run takes for map images when searching directories.
bool IsMapImagePath(const std::string& path);

// Expands the MAP arguments of ag-run in order:
// - an image file (its YAML beside it is used by the import), named by its stem;
// - a directory, searched recursively for images, each named by its path
//   relative to the directory without the extension;
// - a manifest (.tsv or .csv) with a header row naming `path` (required),
//   `name` (optional) and option keys such as `cut.room_width_m`. Relative
//   paths are relative to the manifest.
// Throws InputError for a missing path, a directory without images, a
// manifest without rows, an unreadable manifest row, a name that breaks the
// rule for map names (common/map_name.h) or two maps with the same name, and
// OptionsError for a column that names no option; the message gives the file
// and line. A file with an image's extension in a directory that is not a
// regular file (a FIFO, a device) is skipped, with a line in `notes` saying so.
std::vector<MapEntry> CollectMaps(const std::vector<std::string>& arguments,
                                  std::vector<std::string>* notes = nullptr);

// `base` with the entry's overrides applied. Throws OptionsError naming the
// entry's origin.
proto::PipelineOptions OptionsForMap(const proto::PipelineOptions& base, const MapEntry& entry);

}  // namespace areagraph
