#include "tools/inspect/failure_report.h"

#include <google/protobuf/struct.pb.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "common/error.h"
#include "common/json.h"

namespace areagraph {
namespace {

// A table cell is one line: runners record exception texts, which may not be.
std::string OneLine(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text;
}

}  // namespace

void PrintFailureList(const std::vector<FailureRecord>& failures, std::ostream& out) {
  if (failures.empty()) {
    out << "no failures recorded\n";
    return;
  }
  char line[256];
  std::snprintf(line, sizeof(line), "%-32s %-8s %-24s  %s\n", "map", "stage", "failed at (UTC)",
                "message");
  out << line;
  for (const FailureRecord& failure : failures) {
    std::snprintf(line, sizeof(line), "%-32s %-8s %-24s  ", failure.map_name.c_str(),
                  failure.stage.c_str(), failure.failed_at.c_str());
    out << line << OneLine(failure.message) << "\n";
  }
}

void PrintFailuresJson(const std::vector<FailureRecord>& failures, std::ostream& out) {
  // protobuf's Struct types give JSON with correct escaping for free.
  google::protobuf::ListValue list;
  for (const FailureRecord& failure : failures) {
    auto& fields = *list.add_values()->mutable_struct_value()->mutable_fields();
    fields["map"].set_string_value(failure.map_name);
    fields["stage"].set_string_value(failure.stage);
    fields["failed_at"].set_string_value(failure.failed_at);
    fields["message"].set_string_value(failure.message);
    fields["source_path"].set_string_value(failure.source_path);
  }
  out << MessageToJson(list);
}

void PrintFailedMapsNote(const std::vector<FailureRecord>& failures, std::ostream& out) {
  if (failures.empty()) return;
  out << "\n"
      << failures.size() << (failures.size() == 1 ? " map" : " maps")
      << " failed (ag-inspect --failures shows why):\n";
  char line[256];
  for (const FailureRecord& failure : failures) {
    std::snprintf(line, sizeof(line), "  %-32s failed in %s\n", failure.map_name.c_str(),
                  failure.stage.c_str());
    out << line;
  }
}

}  // namespace areagraph
