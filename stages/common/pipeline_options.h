#pragma once

#include <google/protobuf/message.h>

#include <string>
#include <vector>

#include "proto/pipeline_options.pb.h"

namespace areagraph {

// Reads a PipelineOptions text-format file. Throws OptionsError on a missing
// file or a parse error (with line and column). `room_width_m: auto` means
// `room_width_auto: true`; a number for room_width_m without a
// room_width_auto line means that number (auto off).
proto::PipelineOptions ReadOptionsFile(const std::string& path);

// Applies one "stage.field=value" override, for example
// "cut.room_width_m=1.1". "cut.room_width_m=auto" sets cut.room_width_auto
// and a number clears it. Throws OptionsError naming the valid keys when the
// key is unknown, and saying the expected type when the value does not parse.
void ApplyOverride(const std::string& assignment, proto::PipelineOptions* options);

// Every key that ApplyOverride accepts, as "stage.field".
std::vector<std::string> ValidOptionKeys();

// Sets every unset field to its default, recursively, so that two messages
// that mean the same thing serialize to the same bytes.
void FillDefaults(google::protobuf::Message* message);

// Deterministic bytes of `options` with defaults filled: the options part of
// a cache key.
std::string CanonicalBytes(const google::protobuf::Message& options);

// Human-readable text format of `options` with defaults filled, as stored
// next to each artifact.
std::string CanonicalText(const google::protobuf::Message& options);

}  // namespace areagraph
