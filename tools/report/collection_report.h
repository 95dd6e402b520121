#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace areagraph {

// What WriteCollectionReport wrote.
struct CollectionReport {
  std::string index_path;
  int pages = 0;
  // Maps that failed in the run, and maps whose page could not be written.
  int failed = 0;
};

// ag-run --report DIR: writes DIR/index.html, a sortable table with one row
// per map in `map_names` (thumbnail, areas, passages, W, compute time,
// failure), and DIR/maps/<map>.html, the viewer page (ag-export --format
// html) of each map that has artifacts, from the store at `store_path`.
// Creates DIR. `progress` hears one line per tenth of the maps. Throws
// InputError when DIR cannot be made or written.
CollectionReport WriteCollectionReport(const std::string& store_path,
                                       const std::vector<std::string>& map_names,
                                       const std::string& dir, std::ostream& progress);

// The page file name of a map, relative to the report folder: "maps/" and the
// name with every character outside [A-Za-z0-9._-] turned into '_' (a map
// name from a folder holds '/'), made unique among `taken` (lower case).
std::string MapPageFileName(const std::string& map_name, std::vector<std::string>* taken);

}  // namespace areagraph
