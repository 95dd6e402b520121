#pragma once

#include <string>
#include <vector>

namespace areagraph {

struct ManifestRow {
  int line = 0;  // 1-based line in the file
  std::vector<std::string> cells;
};

// A manifest's header (column names) and rows, every row as wide as the header.
struct ManifestTable {
  std::vector<std::string> header;
  std::vector<ManifestRow> rows;
};

// The file extension of `path` in lower case, with its dot (".csv").
std::string LowerCaseExtension(const std::string& path);

// Whether `path` names a manifest: a .tsv or .csv file, in any case.
bool IsManifestPath(const std::string& path);

// Reads a TSV (.tsv: tab-separated, no quoting) or CSV (.csv: comma-separated,
// RFC 4180 double quotes within one line) manifest. A UTF-8 byte order mark
// is skipped, as are blank lines and lines starting with '#'. Throws InputError with file and line
// for an unreadable file, a missing `path` column, a repeated column, or a row whose width differs
// from the header's.
ManifestTable ReadManifest(const std::string& path);

}  // namespace areagraph
