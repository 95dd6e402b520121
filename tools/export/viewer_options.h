#pragma once

#include <google/protobuf/message.h>

#include <string>
#include <vector>

#include "tools/export/viewer_page.pb.h"

namespace areagraph {

// Parses the options text stored with an artifact of `stage` (canonical text
// format of that stage's message in PipelineOptions) into `options`, whose
// type must be that message, with unset fields at their defaults. Returns
// false when the stage is unknown or the text does not parse (an artifact of
// an older build), leaving `options` at the defaults.
bool ParseStageOptions(const std::string& stage, const std::string& options_text,
                       google::protobuf::Message* options);

// Every option of `stage` with its value and default, in .proto order, for
// the page's options table (non-defaults highlighted). Empty when the text
// does not parse.
std::vector<viewer::OptionValue> StageOptionValues(const std::string& stage,
                                                   const std::string& options_text);

}  // namespace areagraph
