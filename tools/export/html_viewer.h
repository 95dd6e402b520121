#pragma once

#include <string>
#include <vector>

#include "store/artifact_store.h"
#include "tools/export/viewer_page.pb.h"

namespace areagraph {

// The viewer's data for one map: the run behind `key` (a key or unique key
// prefix of any of the map's artifacts; empty: the newest head) and, when
// `compare_key` is not empty, the run behind that key for the diff view.
viewer::Page BuildViewerPage(ArtifactStore& store, const std::string& map_name,
                             const std::string& key, const std::string& compare_key);

// The same from artifacts already read (RunArtifacts): `second`, when not
// null, is the run to compare with.
viewer::Page ViewerPageOf(const std::string& map_name, const std::vector<ArtifactRecord>& first,
                          const std::vector<ArtifactRecord>* second = nullptr);

// The page as one self-contained HTML file: the template, style and script
// of html/ with the data as one JSON blob. It loads nothing at view time
// (its Content-Security-Policy forbids it).
std::string ViewerPageHtml(const viewer::Page& page);

// ag-export --format html: reads the store at `store_path` and writes the page
// of `map_name` to `out_path` (through WriteExportFile). Returns 0.
int ExportViewerPage(const std::string& store_path, const std::string& map_name,
                     const std::string& key, const std::string& compare_key,
                     const std::string& out_path);

}  // namespace areagraph
