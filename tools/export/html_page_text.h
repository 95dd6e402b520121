#pragma once

#include <google/protobuf/message.h>

#include <string>
#include <utility>
#include <vector>

namespace areagraph {

// Pieces shared by the pages that ag-export and ag-run --report write: each
// page is a template (an embedded file) with placeholders filled in once.

// `templ` with each placeholder replaced by its text. Placeholders are found
// in the template itself, so filled-in text is never searched again. Throws
// Error when a placeholder is missing (a broken template).
std::string FillTemplate(const std::string& templ,
                         const std::vector<std::pair<std::string, std::string>>& fills);

// `message` as compact JSON (protobuf's printer, .proto field names) that is
// safe inside <script type="application/json">: every '<' is written \u003c,
// so no "</script>" or "<!--" can end or bend the element.
std::string ScriptJson(const google::protobuf::Message& message);

}  // namespace areagraph
