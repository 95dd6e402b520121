#include "tools/export/html_page_text.h"

#include <google/protobuf/util/json_util.h>

#include <algorithm>

#include "common/error.h"

namespace areagraph {

std::string FillTemplate(const std::string& templ,
                         const std::vector<std::pair<std::string, std::string>>& fills) {
  struct Slot {
    size_t at;
    size_t length;
    const std::string* text;
  };
  std::vector<Slot> slots;
  for (const auto& [placeholder, text] : fills) {
    const size_t at = templ.find(placeholder);
    if (at == std::string::npos) throw Error("page template lacks " + placeholder);
    slots.push_back({at, placeholder.size(), &text});
  }
  std::sort(slots.begin(), slots.end(), [](const Slot& a, const Slot& b) { return a.at < b.at; });
  std::string page;
  size_t from = 0;
  for (const Slot& slot : slots) {
    if (slot.at < from) throw Error("page template has overlapping placeholders");
    page.append(templ, from, slot.at - from);
    page += *slot.text;
    from = slot.at + slot.length;
  }
  page.append(templ, from, std::string::npos);
  return page;
}

std::string ScriptJson(const google::protobuf::Message& message) {
  google::protobuf::util::JsonPrintOptions options;
  options.preserve_proto_field_names = true;
  std::string json;
  const auto status = google::protobuf::util::MessageToJsonString(message, &json, options);
  if (!status.ok()) throw Error("cannot print the page data as JSON: " + status.ToString());
  std::string safe;
  safe.reserve(json.size());
  for (const char c : json) {
    if (c == '<') {
      safe += "\\u003c";  // '<' only occurs inside JSON strings
    } else {
      safe += c;
    }
  }
  return safe;
}

}  // namespace areagraph
