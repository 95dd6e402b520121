#include "stages/common/pipeline_options.h"

#include <google/protobuf/io/coded_stream.h>
#include <google/protobuf/io/tokenizer.h>
#include <google/protobuf/io/zero_copy_stream_impl_lite.h>
#include <google/protobuf/text_format.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <sstream>

#include "common/error.h"
#include "common/input_file.h"

namespace areagraph {
namespace {

using google::protobuf::Descriptor;
using google::protobuf::FieldDescriptor;
using google::protobuf::Message;
using google::protobuf::Reflection;

// Collects parse errors so that the thrown message names the line and column.
class ErrorCollector : public google::protobuf::io::ErrorCollector {
 public:
  void AddError(int line, int column, const std::string& message) override {
    if (first_error.empty()) {
      first_error = "line " + std::to_string(line + 1) + ", column " + std::to_string(column + 1) +
                    ": " + message;
    }
  }
  std::string first_error;
};

std::string JoinKeys(const std::vector<std::string>& keys) {
  std::string joined;
  for (const std::string& key : keys) joined += (joined.empty() ? "" : ", ") + key;
  return joined;
}

// Numeric options that also take the word `auto`, which stands for 0: the
// stage estimates the number from the map.
struct AutoOption {
  const char* stage;
  const char* number_field;
};
constexpr AutoOption kAutoOptions[] = {{"cut", "room_width_m"}};

Message* StageMessage(proto::PipelineOptions* options, const std::string& stage_name) {
  const FieldDescriptor* stage = proto::PipelineOptions::descriptor()->FindFieldByName(stage_name);
  return options->GetReflection()->MutableMessage(options, stage);
}

// `room_width_m: auto` -> `room_width_m: 0`, before the text parser (which
// wants a number) sees it.
std::string RewriteAutoWords(std::string text) {
  for (const AutoOption& option : kAutoOptions) {
    const std::regex word(std::string("\\b") + option.number_field + "\\s*:\\s*auto\\b");
    text = std::regex_replace(text, word, std::string(option.number_field) + ": 0");
  }
  return text;
}

// The text parser skips reserved field names without a word, so a file
// written for an older build would lose its switches silently: a removed
// option in `text` (comments stripped) throws OptionsError naming it.
void RefuseRemovedOptions(const std::string& text, const std::string& path) {
  const std::string code = std::regex_replace(text, std::regex("#[^\\n]*"), "");
  const Descriptor* pipeline = proto::PipelineOptions::descriptor();
  for (int i = 0; i < pipeline->field_count(); ++i) {
    const FieldDescriptor* stage = pipeline->field(i);
    const Descriptor* options = stage->message_type();
    for (int k = 0; k < options->reserved_name_count(); ++k) {
      const std::string& name = options->reserved_name(k);
      if (!std::regex_search(code, std::regex("\\b" + name + "\\s*[:{]"))) continue;
      throw OptionsError("options file '" + path + "': option '" + stage->name() + "." + name +
                         "' was removed (proto/pipeline_options.proto says what replaced it)");
    }
  }
}

// The values a numeric option may take, from the unit its name ends in.
struct NumberRange {
  double max;
  const char* unit;
};

bool EndsWith(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

NumberRange RangeOf(const FieldDescriptor& field) {
  if (EndsWith(field.name(), "_m2")) return {kMaxOptionAreaM2, "square metres"};
  if (EndsWith(field.name(), "_m")) return {kMaxOptionLengthM, "metres"};
  if (EndsWith(field.name(), "_percent")) return {100, "percent"};
  return {kMaxOptionLengthM, ""};
}

std::string NumberText(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

// Throws OptionsError when a set floating-point field of `options` (a
// stage's options, or a message within them, named `prefix`) is not finite
// or lies outside the range of its unit, or an integer is negative.
void CheckNumbersOfStage(const std::string& prefix, const Message& options) {
  const Descriptor* descriptor = options.GetDescriptor();
  const Reflection* reflection = options.GetReflection();
  for (int i = 0; i < descriptor->field_count(); ++i) {
    const FieldDescriptor* field = descriptor->field(i);
    if (field->is_repeated() || !reflection->HasField(options, field)) continue;
    double value = 0;
    switch (field->cpp_type()) {
      case FieldDescriptor::CPPTYPE_MESSAGE:
        CheckNumbersOfStage(prefix + "." + field->name(), reflection->GetMessage(options, field));
        continue;
      case FieldDescriptor::CPPTYPE_DOUBLE:
        value = reflection->GetDouble(options, field);
        break;
      case FieldDescriptor::CPPTYPE_FLOAT:
        value = reflection->GetFloat(options, field);
        break;
      case FieldDescriptor::CPPTYPE_INT32:
      case FieldDescriptor::CPPTYPE_INT64: {
        // Counts, grey values and limits: never negative; the stages check the rest.
        const int64_t count = field->cpp_type() == FieldDescriptor::CPPTYPE_INT32
                                  ? reflection->GetInt32(options, field)
                                  : reflection->GetInt64(options, field);
        if (count >= 0) continue;
        throw OptionsError("option '" + prefix + "." + field->name() +
                           "' must not be negative, got " + std::to_string(count));
      }
      default:
        continue;
    }
    const NumberRange range = RangeOf(*field);
    if (value >= 0 && value <= range.max) continue;  // NaN fails both
    throw OptionsError("option '" + prefix + "." + field->name() + "' must be a number" +
                       (*range.unit != '\0' ? std::string(" of ") + range.unit : "") + " in [0, " +
                       NumberText(range.max) + "], got " + NumberText(value));
  }
}

// Every key within `options` (a stage's options or a message within them),
// each "prefix.field", a message's fields as "prefix.message.field".
void AddKeys(const Descriptor* options, const std::string& prefix, std::vector<std::string>* keys) {
  for (int j = 0; j < options->field_count(); ++j) {
    const FieldDescriptor* field = options->field(j);
    if (field->cpp_type() == FieldDescriptor::CPPTYPE_MESSAGE && !field->is_repeated()) {
      AddKeys(field->message_type(), prefix + "." + field->name(), keys);
    } else {
      keys->push_back(prefix + "." + field->name());
    }
  }
}

// "true"/"false" or "1"/"0" in any letter case; nullopt otherwise.
std::optional<bool> ParseBool(std::string value) {
  std::transform(value.begin(), value.end(), value.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (value == "true" || value == "1") return true;
  if (value == "false" || value == "0") return false;
  return std::nullopt;
}

}  // namespace

void CheckOptionNumbers(const proto::PipelineOptions& options) {
  const Descriptor* pipeline = proto::PipelineOptions::descriptor();
  for (int i = 0; i < pipeline->field_count(); ++i) {
    const FieldDescriptor* stage = pipeline->field(i);
    CheckNumbersOfStage(stage->name(), options.GetReflection()->GetMessage(options, stage));
  }
}

proto::PipelineOptions ReadOptionsFile(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw InputError("options file '" + path + "' is a folder; name a .pbtxt file");
  }
  std::string text = ReadInputFile(path, "options file '" + path + "'");
  // Editors on some systems save UTF-8 with a byte-order mark; it is no part of the options.
  if (text.rfind(kUtf8ByteOrderMark, 0) == 0) text.erase(0, std::strlen(kUtf8ByteOrderMark));
  proto::PipelineOptions options;
  google::protobuf::TextFormat::Parser parser;
  ErrorCollector errors;
  parser.RecordErrorsTo(&errors);
  if (!parser.ParseFromString(RewriteAutoWords(text), &options)) {
    throw OptionsError("options file '" + path + "', " + errors.first_error);
  }
  RefuseRemovedOptions(text, path);
  try {
    CheckOptionNumbers(options);
  } catch (const OptionsError& error) {
    throw OptionsError("options file '" + path + "': " + error.what());
  }
  return options;
}

std::vector<std::string> ValidOptionKeys() {
  std::vector<std::string> keys;
  const Descriptor* pipeline = proto::PipelineOptions::descriptor();
  for (int i = 0; i < pipeline->field_count(); ++i) {
    const FieldDescriptor* stage = pipeline->field(i);
    AddKeys(stage->message_type(), stage->name(), &keys);
  }
  return keys;
}

void ApplyOverride(const std::string& assignment, proto::PipelineOptions* options) {
  const size_t equals = assignment.find('=');
  const size_t dot = assignment.find('.');
  if (equals == std::string::npos || dot == std::string::npos || dot > equals) {
    throw OptionsError("--set expects stage.field=value, got '" + assignment +
                       "'; valid keys: " + JoinKeys(ValidOptionKeys()));
  }
  const std::string stage_name = assignment.substr(0, dot);
  const std::string key = assignment.substr(0, equals);
  const std::string value = assignment.substr(equals + 1);

  // The stage's options, then each message named on the way to the field.
  const FieldDescriptor* stage = proto::PipelineOptions::descriptor()->FindFieldByName(stage_name);
  Message* owner = stage == nullptr ? nullptr : StageMessage(options, stage_name);
  const FieldDescriptor* field = nullptr;
  std::string field_name;
  size_t at = dot + 1;
  while (owner != nullptr) {
    const size_t next = key.find('.', at);
    field_name = key.substr(at, next == std::string::npos ? std::string::npos : next - at);
    field = owner->GetDescriptor()->FindFieldByName(field_name);
    if (field == nullptr || next == std::string::npos) break;
    if (field->cpp_type() != FieldDescriptor::CPPTYPE_MESSAGE || field->is_repeated()) {
      field = nullptr;
      break;
    }
    owner = owner->GetReflection()->MutableMessage(owner, field);
    at = next + 1;
  }
  if (field == nullptr || field->cpp_type() == FieldDescriptor::CPPTYPE_MESSAGE) {
    throw OptionsError("unknown option '" + key + "'; valid keys: " + JoinKeys(ValidOptionKeys()));
  }
  const AutoOption* auto_option = nullptr;
  for (const AutoOption& option : kAutoOptions) {
    if (key == std::string(option.stage) + "." + option.number_field) auto_option = &option;
  }
  if (auto_option != nullptr && value == "auto") {
    owner->GetReflection()->SetDouble(owner, field, 0);
    return;
  }
  if (field->is_repeated()) {
    // A list: comma-separated values replace it; an empty value clears it.
    owner->GetReflection()->ClearField(owner, field);
    std::stringstream items(value);
    std::string item;
    while (std::getline(items, item, ',')) {
      google::protobuf::TextFormat::Parser parser;
      ErrorCollector errors;
      parser.RecordErrorsTo(&errors);
      if (!parser.ParseFieldValueFromString(item, field, owner)) {
        std::string expected = field->type_name();
        if (const google::protobuf::EnumDescriptor* names = field->enum_type()) {
          expected.clear();
          for (int i = 0; i < names->value_count(); ++i) {
            expected += (i == 0 ? "" : ", ") + names->value(i)->name();
          }
        }
        throw OptionsError("option '" + key + "' expects a comma-separated list of " + expected +
                           ", got '" + item + "'");
      }
    }
    return;
  }
  if (field->cpp_type() == FieldDescriptor::CPPTYPE_BOOL) {
    const std::optional<bool> flag = ParseBool(value);
    if (!flag) {
      throw OptionsError("option '" + key + "' expects true or false (or 1 or 0), got '" + value +
                         "'");
    }
    owner->GetReflection()->SetBool(owner, field, *flag);
    return;
  }
  google::protobuf::TextFormat::Parser parser;
  ErrorCollector errors;  // keeps protobuf from logging its own line to stderr
  parser.RecordErrorsTo(&errors);
  if (!parser.ParseFieldValueFromString(value, field, owner)) {
    throw OptionsError("option '" + key + "' expects a " + field->type_name() +
                       (auto_option != nullptr ? " or auto" : "") + ", got '" + value + "'");
  }
  CheckNumbersOfStage(stage_name, *StageMessage(options, stage_name));
}

void FillDefaults(Message* message) {
  const Descriptor* descriptor = message->GetDescriptor();
  const Reflection* reflection = message->GetReflection();
  for (int i = 0; i < descriptor->field_count(); ++i) {
    const FieldDescriptor* field = descriptor->field(i);
    if (field->is_repeated()) continue;
    if (field->cpp_type() == FieldDescriptor::CPPTYPE_MESSAGE) {
      FillDefaults(reflection->MutableMessage(message, field));
      continue;
    }
    if (reflection->HasField(*message, field)) continue;
    switch (field->cpp_type()) {
      case FieldDescriptor::CPPTYPE_INT32:
        reflection->SetInt32(message, field, field->default_value_int32());
        break;
      case FieldDescriptor::CPPTYPE_INT64:
        reflection->SetInt64(message, field, field->default_value_int64());
        break;
      case FieldDescriptor::CPPTYPE_UINT32:
        reflection->SetUInt32(message, field, field->default_value_uint32());
        break;
      case FieldDescriptor::CPPTYPE_UINT64:
        reflection->SetUInt64(message, field, field->default_value_uint64());
        break;
      case FieldDescriptor::CPPTYPE_DOUBLE:
        reflection->SetDouble(message, field, field->default_value_double());
        break;
      case FieldDescriptor::CPPTYPE_FLOAT:
        reflection->SetFloat(message, field, field->default_value_float());
        break;
      case FieldDescriptor::CPPTYPE_BOOL:
        reflection->SetBool(message, field, field->default_value_bool());
        break;
      case FieldDescriptor::CPPTYPE_ENUM:
        reflection->SetEnum(message, field, field->default_value_enum());
        break;
      case FieldDescriptor::CPPTYPE_STRING:
        reflection->SetString(message, field, field->default_value_string());
        break;
      case FieldDescriptor::CPPTYPE_MESSAGE:
        break;
    }
  }
}

std::string CanonicalBytes(const Message& options) {
  std::unique_ptr<Message> filled(options.New());
  filled->CopyFrom(options);
  FillDefaults(filled.get());
  std::string bytes;
  {
    google::protobuf::io::StringOutputStream raw(&bytes);
    google::protobuf::io::CodedOutputStream coded(&raw);
    coded.SetSerializationDeterministic(true);
    filled->SerializeToCodedStream(&coded);
  }
  return bytes;
}

std::string CanonicalText(const Message& options) {
  std::unique_ptr<Message> filled(options.New());
  filled->CopyFrom(options);
  FillDefaults(filled.get());
  std::string text;
  google::protobuf::TextFormat::PrintToString(*filled, &text);
  return text;
}

}  // namespace areagraph
