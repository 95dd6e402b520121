#include "tools/export/viewer_options.h"

#include <google/protobuf/text_format.h>

#include <memory>

#include "proto/pipeline_options.pb.h"
#include "stages/common/pipeline_options.h"

namespace areagraph {
namespace {

using google::protobuf::FieldDescriptor;
using google::protobuf::Message;

// A new message of the type that PipelineOptions holds for `stage`, or null.
std::unique_ptr<Message> NewStageOptions(const std::string& stage) {
  const FieldDescriptor* field = proto::PipelineOptions::descriptor()->FindFieldByName(stage);
  if (field == nullptr || field->type() != FieldDescriptor::TYPE_MESSAGE) return nullptr;
  return std::unique_ptr<Message>(
      proto::PipelineOptions::default_instance()
          .GetReflection()
          ->GetMessage(proto::PipelineOptions::default_instance(), field)
          .New());
}

// A field's value as text format writes it (1.25, true, 18).
std::string FieldText(const Message& message, const FieldDescriptor* field) {
  std::string text;
  google::protobuf::TextFormat::PrintFieldValueToString(message, field, -1, &text);
  return text;
}

}  // namespace

bool ParseStageOptions(const std::string& stage, const std::string& options_text,
                       Message* options) {
  options->Clear();
  const std::unique_ptr<Message> expected = NewStageOptions(stage);
  const bool parsed = expected && expected->GetDescriptor() == options->GetDescriptor() &&
                      google::protobuf::TextFormat::ParseFromString(options_text, options);
  if (!parsed) options->Clear();
  FillDefaults(options);
  return parsed;
}

std::vector<viewer::OptionValue> StageOptionValues(const std::string& stage,
                                                   const std::string& options_text) {
  std::vector<viewer::OptionValue> values;
  const std::unique_ptr<Message> options = NewStageOptions(stage);
  if (!options || !ParseStageOptions(stage, options_text, options.get())) return values;
  const std::unique_ptr<Message> defaults(options->New());
  FillDefaults(defaults.get());
  const auto* descriptor = options->GetDescriptor();
  for (int i = 0; i < descriptor->field_count(); ++i) {
    const FieldDescriptor* field = descriptor->field(i);
    if (field->is_repeated() || field->type() == FieldDescriptor::TYPE_MESSAGE) continue;
    viewer::OptionValue value;
    value.set_name(field->name());
    value.set_value(FieldText(*options, field));
    value.set_default_value(FieldText(*defaults, field));
    value.set_is_default(value.value() == value.default_value());
    values.push_back(value);
  }
  return values;
}

}  // namespace areagraph
