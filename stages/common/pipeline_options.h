#pragma once

#include <google/protobuf/message.h>

#include <string>
#include <vector>

#include "proto/pipeline_options.pb.h"

namespace areagraph {

// Bounds of every floating-point option, by the unit its name ends in (_m,
// _m2; _percent is at most 100): no option makes sense beyond them, and
// lengths this large overflow once converted to pixels.
inline constexpr double kMaxOptionLengthM = 1e4;
inline constexpr double kMaxOptionAreaM2 = 1e8;

// Throws OptionsError naming the option when a set floating-point option is
// not finite, negative, or beyond the bound of its unit, or when an integer
// option is negative (the stages check the finer ranges). ReadOptionsFile and
// ApplyOverride call it, so options from files, --set and manifests are
// checked before any map is read.
void CheckOptionNumbers(const proto::PipelineOptions& options);

// Reads a PipelineOptions text-format file. Throws OptionsError on a missing
// file, a folder, a parse error (with line and column) or a number out of
// range. `room_width_m: auto` means `room_width_m: 0` (W from the map).
proto::PipelineOptions ReadOptionsFile(const std::string& path);

// Applies one "stage.field=value" override, for example
// "cut.room_width_m=1.1". "cut.room_width_m=auto" sets it to 0 (W from the
// map). A boolean takes true or false (any letter case) or
// 1 or 0. Throws OptionsError naming the valid keys when the key is unknown,
// saying the expected type when the value does not parse, and the range when
// a number is out of it (see CheckOptionNumbers).
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
