#include "runner/run/map_collection.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>

#include "common/error.h"
#include "common/input_file.h"
#include "common/map_name.h"
#include "runner/run/manifest_reader.h"
#include "stages/common/pipeline_options.h"

namespace areagraph {
namespace {

namespace fs = std::filesystem;

void AddDirectory(const std::string& directory, std::vector<MapEntry>* entries,
                  std::vector<std::string>* notes) {
  std::vector<fs::path> images;
  std::error_code error;
  for (fs::recursive_directory_iterator it(directory, error), end; !error && it != end;
       it.increment(error)) {
    if (!IsMapImagePath(it->path().string())) continue;
    if (it->is_regular_file(error)) {
      images.push_back(it->path());
    } else if (const std::string kind = SpecialFileKind(it->path().string()); !kind.empty()) {
      // Reading it could wait for ever (a FIFO) or never end (a device).
      if (notes != nullptr) {
        notes->push_back("skipping '" + it->path().string() + "': it is " + kind +
                         ", not a regular file");
      }
    }
  }
  if (error) {
    throw InputError("cannot search directory '" + directory + "': " + error.message());
  }
  if (images.empty()) {
    throw InputError("directory '" + directory +
                     "' holds no map images (.png, .pgm, .ppm, .pbm, .jpg, .jpeg, .bmp, .tif, "
                     ".tiff), not even in subfolders");
  }
  std::sort(images.begin(), images.end());
  for (const fs::path& image : images) {
    fs::path relative = image.lexically_relative(directory);
    relative.replace_extension();
    entries->push_back({relative.generic_string(), image.string(), {}, image.string()});
  }
}

// A column that names no option fails before any map runs, with every valid key.
void CheckManifestColumns(const std::string& manifest, const std::vector<std::string>& header) {
  const std::vector<std::string> keys = ValidOptionKeys();
  for (const std::string& column : header) {
    if (column == "path" || column == "name") continue;
    if (std::find(keys.begin(), keys.end(), column) == keys.end()) {
      std::string valid;
      for (const std::string& key : keys) valid += (valid.empty() ? "" : ", ") + key;
      throw OptionsError(manifest + ": column '" + column +
                         "' is not an option; columns are path, name and option keys: " + valid);
    }
  }
}

void AddManifest(const std::string& manifest, std::vector<MapEntry>* entries) {
  const ManifestTable table = ReadManifest(manifest);
  CheckManifestColumns(manifest, table.header);
  if (table.rows.empty()) {
    throw InputError("manifest '" + manifest + "' lists no maps (it has only its header)");
  }
  const fs::path base = fs::path(manifest).parent_path();
  for (const ManifestRow& row : table.rows) {
    MapEntry entry;
    entry.origin = manifest + ":" + std::to_string(row.line);
    for (size_t column = 0; column < table.header.size(); ++column) {
      const std::string& key = table.header[column];
      const std::string& value = row.cells[column];
      if (key == "path") {
        entry.path = fs::path(value).is_absolute() ? value : (base / value).string();
      } else if (key == "name") {
        entry.name = value;
      } else if (!value.empty()) {
        entry.overrides.push_back(key + "=" + value);
      }
    }
    if (entry.path.empty()) throw InputError(entry.origin + ": the path is empty");
    if (entry.name.empty()) entry.name = fs::path(entry.path).stem().string();
    entries->push_back(std::move(entry));
  }
}

}  // namespace

bool IsMapImagePath(const std::string& path) {
  static const std::set<std::string> kExtensions = {".png",  ".pgm", ".ppm", ".pbm", ".jpg",
                                                    ".jpeg", ".bmp", ".tif", ".tiff"};
  return kExtensions.count(LowerCaseExtension(path)) > 0;
}

std::vector<MapEntry> CollectMaps(const std::vector<std::string>& arguments,
                                  std::vector<std::string>* notes) {
  std::vector<MapEntry> entries;
  for (const std::string& argument : arguments) {
    std::error_code error;
    if (fs::is_directory(argument, error)) {
      AddDirectory(argument, &entries, notes);
    } else if (!fs::exists(argument, error)) {
      throw InputError("'" + argument + "' does not exist");
    } else if (IsManifestPath(argument)) {
      AddManifest(argument, &entries);
    } else {
      entries.push_back({fs::path(argument).stem().string(), argument, {}, argument});
    }
  }
  std::set<std::string> names;
  for (const MapEntry& entry : entries) {
    try {
      CheckMapName(entry.name);
    } catch (const InputError& error) {
      throw InputError(entry.origin + ": " + error.what() +
                       " (rename the file, or give it a `name` in a manifest)");
    }
    if (!names.insert(entry.name).second) {
      throw InputError(entry.origin + ": a second map named '" + entry.name +
                       "'; map names must be unique (give a `name` column in a manifest)");
    }
  }
  return entries;
}

proto::PipelineOptions OptionsForMap(const proto::PipelineOptions& base, const MapEntry& entry) {
  proto::PipelineOptions options = base;
  for (const std::string& assignment : entry.overrides) {
    try {
      ApplyOverride(assignment, &options);
    } catch (const OptionsError& error) {
      throw OptionsError(entry.origin + ": " + error.what());
    }
  }
  return options;
}

}  // namespace areagraph
