// docs/architecture.md's stage table against the stage table in code: every
// row's name and version, in pipeline order, so that the page stays true when
// a stage's version is bumped (stages/common/stage_info.h) or a stage added.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <sstream>
#include <string>
#include <vector>

#include "stages/pipeline/stage_table.h"
#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

std::string Trimmed(const std::string& text) {
  const size_t begin = text.find_first_not_of(" \t\r");
  if (begin == std::string::npos) return "";
  return text.substr(begin, text.find_last_not_of(" \t\r") - begin + 1);
}

std::string Lowered(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// The cells of a Markdown table line ("| a | b |"), trimmed; "\|" stays in
// its cell as "|". Empty when the line is not a table line.
std::vector<std::string> TableCells(const std::string& line) {
  const std::string row = Trimmed(line);
  if (row.empty() || row.front() != '|') return {};
  std::vector<std::string> cells;
  std::string cell;
  for (size_t i = 1; i < row.size(); ++i) {
    if (row[i] == '\\' && i + 1 < row.size() && row[i + 1] == '|') {
      cell += '|';
      ++i;
    } else if (row[i] == '|') {
      cells.push_back(Trimmed(cell));
      cell.clear();
    } else {
      cell += row[i];
    }
  }
  if (!Trimmed(cell).empty()) cells.push_back(Trimmed(cell));
  return cells;
}

// A cell without Markdown's code and bold marks: "`cut`", "**cut**" -> "cut".
std::string PlainText(const std::string& cell) {
  std::string plain;
  for (const char c : cell) {
    if (c != '`' && c != '*') plain += c;
  }
  return Trimmed(plain);
}

bool IsDelimiterRow(const std::vector<std::string>& cells) {
  if (cells.empty()) return false;
  return std::all_of(cells.begin(), cells.end(), [](const std::string& cell) {
    return !cell.empty() && cell.find_first_not_of(":-") == std::string::npos &&
           cell.find('-') != std::string::npos;
  });
}

struct DocumentedStage {
  std::string name;
  std::string version;
};

// The rows of the first table whose header begins with "row" (or "stage") and
// "version", in the order they stand.
std::vector<DocumentedStage> DocumentedStages(const std::string& markdown) {
  std::istringstream lines(markdown);
  std::string line;
  bool in_table = false;
  bool after_header = false;
  std::vector<DocumentedStage> stages;
  while (std::getline(lines, line)) {
    const std::vector<std::string> cells = TableCells(line);
    if (!in_table) {
      const bool header =
          cells.size() >= 2 &&
          (Lowered(PlainText(cells[0])) == "row" || Lowered(PlainText(cells[0])) == "stage") &&
          Lowered(PlainText(cells[1])) == "version";
      if (header) in_table = after_header = true;
      continue;
    }
    if (after_header) {
      after_header = false;
      if (IsDelimiterRow(cells)) continue;
      return {};  // a header without its delimiter row is no table
    }
    if (cells.empty()) break;
    stages.push_back({PlainText(cells[0]), cells.size() > 1 ? PlainText(cells[1]) : ""});
  }
  return stages;
}

// Where the documented table differs from StageTable(), one line each; empty
// when every row names the same stage with the same version, in order.
std::vector<std::string> DifferencesFromCode(const std::string& markdown) {
  const std::vector<DocumentedStage> documented = DocumentedStages(markdown);
  if (documented.empty()) return {"no stage table (header \"| row | version | ...\") found"};
  std::vector<std::string> differences;
  const std::vector<StageDefinition>& table = StageTable();
  for (size_t i = 0; i < std::max(documented.size(), table.size()); ++i) {
    const std::string row = "row " + std::to_string(i + 1) + ": ";
    if (i >= documented.size()) {
      differences.push_back(row + "stage '" + table[i].info.name + "' is not documented");
      continue;
    }
    if (i >= table.size()) {
      differences.push_back(row + "'" + documented[i].name + "' is no stage of the code");
      continue;
    }
    const StageInfo& info = table[i].info;
    if (documented[i].name != info.name) {
      differences.push_back(row + "documented '" + documented[i].name + "', the code has '" +
                            info.name + "'");
    }
    if (documented[i].version != std::to_string(info.version)) {
      differences.push_back(row + info.name + " version documented '" + documented[i].version +
                            "', stage_info.h has " + std::to_string(info.version));
    }
  }
  return differences;
}

std::string ArchitecturePage() { return ReadFile(SourcePath("docs/architecture.md")); }

// `markdown` with the first occurrence of `from` replaced by `to`.
std::string Edited(std::string markdown, const std::string& from, const std::string& to) {
  const size_t at = markdown.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) markdown.replace(at, from.size(), to);
  return markdown;
}

TEST(ArchitectureDocTest, StageTableNamesEveryStageWithItsVersion) {
  const std::vector<std::string> differences = DifferencesFromCode(ArchitecturePage());
  EXPECT_TRUE(differences.empty())
      << "docs/architecture.md, \"The stage table\", disagrees with stages/common:\n"
      << ::testing::PrintToString(differences);
}

TEST(ArchitectureDocTest, ReadsTheTableWhateverItsFormatting) {
  const std::string markdown =
      "Text | with a pipe\n\n"
      "| **Stage** | Version | writes |\n"
      "|:---|--:|---|\n"
      "| `import` | 1 | GridMap \\| more |\n"
      "|  clean  |  4  |\n"
      "\n| row | version |\n|---|---|\n| later | 9 |\n";
  const std::vector<DocumentedStage> stages = DocumentedStages(markdown);
  ASSERT_EQ(stages.size(), 2u);
  EXPECT_EQ(stages[0].name, "import");
  EXPECT_EQ(stages[0].version, "1");
  EXPECT_EQ(stages[1].name, "clean");
  EXPECT_EQ(stages[1].version, "4");
  EXPECT_TRUE(DocumentedStages("| row | version |\n| prune | 4 |\n").empty());
}

// The page's own table with one thing changed must fail: the check above is
// not satisfied by any table.
TEST(ArchitectureDocTest, AnyChangedRowIsReported) {
  const std::string page = ArchitecturePage();
  const StageInfo& prune = kPruneStage;
  const std::string prune_row =
      "| " + std::string(prune.name) + " | " + std::to_string(prune.version) + " |";
  ASSERT_NE(page.find(prune_row), std::string::npos) << prune_row;

  const std::string bumped = "| prune | " + std::to_string(prune.version + 1) + " |";
  const std::vector<std::string> version = DifferencesFromCode(Edited(page, prune_row, bumped));
  ASSERT_EQ(version.size(), 1u) << ::testing::PrintToString(version);
  EXPECT_NE(version[0].find("prune version"), std::string::npos) << version[0];

  const std::string renamed = "| pruning | " + std::to_string(prune.version) + " |";
  EXPECT_EQ(DifferencesFromCode(Edited(page, prune_row, renamed)).size(), 1u);

  const std::string not_a_number = "| prune | " + std::to_string(prune.version) + "a |";
  EXPECT_EQ(DifferencesFromCode(Edited(page, prune_row, not_a_number)).size(), 1u);

  const size_t row_start = page.find(prune_row);
  std::string dropped = page;
  dropped.erase(row_start, page.find('\n', row_start) + 1 - row_start);
  EXPECT_FALSE(DifferencesFromCode(dropped).empty());

  EXPECT_FALSE(DifferencesFromCode("# Architecture\n\nNo table.\n").empty());
}

}  // namespace
}  // namespace areagraph::testing
