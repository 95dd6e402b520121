#include "runner/run/manifest_reader.h"

#include <algorithm>
#include <filesystem>
#include <set>
#include <sstream>

#include "common/error.h"
#include "common/input_file.h"

namespace areagraph {
namespace {

std::string Trim(const std::string& text) {
  const size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string> SplitTsv(const std::string& line) {
  std::vector<std::string> cells;
  size_t start = 0;
  while (true) {
    const size_t tab = line.find('\t', start);
    cells.push_back(Trim(line.substr(start, tab - start)));
    if (tab == std::string::npos) return cells;
    start = tab + 1;
  }
}

// One CSV line; quoted cells may hold commas and doubled quotes.
std::vector<std::string> SplitCsv(const std::string& line, const std::string& where) {
  std::vector<std::string> cells;
  std::string cell;
  bool quoted = false, was_quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cell += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cell += c;
      }
    } else if (c == '"' && Trim(cell).empty()) {
      quoted = was_quoted = true;
      cell.clear();
    } else if (c == ',') {
      cells.push_back(was_quoted ? cell : Trim(cell));
      cell.clear();
      was_quoted = false;
    } else {
      cell += c;
    }
  }
  if (quoted) throw InputError(where + ": a quoted field is not closed");
  cells.push_back(was_quoted ? cell : Trim(cell));
  return cells;
}

}  // namespace

std::string LowerCaseExtension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

bool IsManifestPath(const std::string& path) {
  const std::string extension = LowerCaseExtension(path);
  return extension == ".tsv" || extension == ".csv";
}

ManifestTable ReadManifest(const std::string& path) {
  std::istringstream file(ReadInputFile(path, "manifest '" + path + "'"));
  const bool csv = LowerCaseExtension(path) == ".csv";
  ManifestTable table;
  std::string line;
  for (int number = 1; std::getline(file, line); ++number) {
    const std::string where = path + ":" + std::to_string(number);
    // Spreadsheets save UTF-8 CSV with a byte order mark; it is no part of a name.
    if (number == 1 && line.rfind(kUtf8ByteOrderMark, 0) == 0) line.erase(0, 3);
    if (line.find('\0') != std::string::npos) {
      throw InputError(where + ": not a text line (the manifest must be TSV or CSV text)");
    }
    const std::string trimmed = Trim(line);
    if (trimmed.empty() || trimmed[0] == '#') continue;
    std::vector<std::string> cells = csv ? SplitCsv(line, where) : SplitTsv(line);
    if (table.header.empty()) {
      std::set<std::string> seen;
      for (const std::string& column : cells) {
        if (column.empty()) throw InputError(where + ": a header column has no name");
        if (!seen.insert(column).second) {
          throw InputError(where + ": column '" + column + "' appears twice");
        }
      }
      if (!seen.count("path")) {
        throw InputError(where + ": the header has no `path` column (columns: path, name, " +
                         "option keys)");
      }
      table.header = std::move(cells);
      continue;
    }
    if (cells.size() != table.header.size()) {
      throw InputError(where + ": " + std::to_string(cells.size()) +
                       " fields, but the header has " + std::to_string(table.header.size()));
    }
    table.rows.push_back({number, std::move(cells)});
  }
  if (table.header.empty()) throw InputError("manifest '" + path + "' is empty");
  return table;
}

}  // namespace areagraph
