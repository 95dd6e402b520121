#pragma once

#include <google/protobuf/message.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "proto/pipeline_options.pb.h"
#include "stages/common/stage_info.h"

namespace areagraph {

using MessagePtr = std::unique_ptr<google::protobuf::Message>;

// Called by a stage's compute with the index of an input it reads no more:
// the caller may free that input before the stage finishes. It also carries
// the caller's hook for the points between a compute's big steps.
class InputRelease {
 public:
  using Take = std::function<std::shared_ptr<google::protobuf::Message>(size_t input)>;
  // `release` frees input i; `take` hands it over (see TakeInput), or is
  // empty; `between_steps` is the hook below, or empty.
  template <typename Release>
  InputRelease(Release release, Take take = {},  // NOLINT: a plain function converts
               std::function<void()> between_steps = {})
      : release_(std::move(release)),
        take_(std::move(take)),
        between_steps_(std::move(between_steps)) {}
  void operator()(size_t input) const { release_(input); }
  // Input i itself, for a compute that frees parts of it as it goes, when the
  // caller holds the only reference (the memo's last reader, or a parsed
  // input); else null, and the input stays read-only. inputs[i] stays valid
  // while the result lives.
  std::shared_ptr<google::protobuf::Message> TakeInput(size_t input) const {
    return take_ ? take_(input) : nullptr;
  }
  // What a compute calls where one big step's scratch is freed and the next
  // allocates afresh (cut: at its start, after its room-width estimate): a
  // program may give freed memory back there. Empty when the caller has none.
  const std::function<void()>& between_steps() const { return between_steps_; }

 private:
  std::function<void(size_t input)> release_;
  Take take_;
  std::function<void()> between_steps_;
};

// Everything the executables, the runner and the tools know about one stage.
// Each stage is one row of StageTable(); nothing else lists the stages.
struct StageDefinition {
  StageInfo info;
  // The stages whose artifacts it reads, in the order their keys enter its
  // cache key. Empty for import, which reads a file.
  std::vector<StageInfo> inputs;
  // Its options within PipelineOptions.
  const google::protobuf::Message& (*options_of)(const proto::PipelineOptions& options);
  // An empty message of the artifact type it writes.
  const google::protobuf::Message* prototype;
  // The format_version it writes (stage_info.h).
  uint32_t format_version;
  // The artifact type's full name, as the store's proto_type records it, and
  // the format_version of a parsed artifact of that type: what reading an
  // artifact checks, here so that a reader need not build protobuf's
  // descriptors for it (0.9 M instructions of ag-render's 28 M).
  // stage_table_test ties both to `prototype`.
  const char* proto_type;
  uint32_t (*format_version_of)(const google::protobuf::Message& artifact);
  // Computes its artifact from its input artifacts (in `inputs` order, each of
  // its stage's artifact type), calling `release` for an input it is done
  // with early (prune: the Voronoi diagram); inputs[i] is dangling after.
  // Null for import. Throws what the stage throws.
  MessagePtr (*compute)(const std::vector<const google::protobuf::Message*>& inputs,
                        const InputRelease& release, const proto::PipelineOptions& options);
  // One line about an artifact of this stage, e.g. "12 areas, 11 passages";
  // stored beside the artifact, so that a cache hit prints it unparsed.
  std::string (*summarize)(const google::protobuf::Message& artifact);
  // What the stage does: the --help text of its executable.
  const char* description;

  // For a stage that also reads its own previous version (match, which keeps
  // ids stable across a map's Area Graphs): computes the artifact from the
  // inputs and `previous`, its head before the run (null for a map's first
  // version), given `version` (the previous key and the new number). Such a
  // stage has `compute` null; its previous version's key enters its cache key
  // after the inputs' keys, and each artifact it writes is recorded in the
  // map's history (see docs/architecture.md, "Stages that read their previous
  // version"). Null for every other stage.
  MessagePtr (*compute_next_version)(const std::vector<const google::protobuf::Message*>& inputs,
                                     const google::protobuf::Message* previous,
                                     const VersionLink& version,
                                     const proto::PipelineOptions& options) = nullptr;

  bool reads_previous_version() const { return compute_next_version != nullptr; }
};

// Every stage, in pipeline order: import first, match last.
const std::vector<StageDefinition>& StageTable();

// The row of `stage`.
const StageDefinition& StageOf(const StageInfo& stage);

// The row of the stage called `name`; throws OptionsError listing the stages
// when there is none. `what` names where the name came from, e.g. "--from".
const StageDefinition& FindStage(const std::string& name, const std::string& what = "stage");

// "import, clean, voronoi, prune, cut, merge, match": for help texts and errors.
std::string StageNameList();

// The stages that read artifacts (all but import), in pipeline order.
std::vector<StageInfo> PipelineStages();

// The last stage: the one whose head is a map's Area Graph as published.
const StageInfo& FinalStage();

// The names of the stages that read a file instead (import): what
// ArtifactStore::Verify must not look up as artifacts.
std::vector<std::string> FileInputStageNames();

// A new, empty message of the artifact type named `proto_type` (as stored in
// the artifacts table), or nullptr for a type this build does not know.
MessagePtr NewArtifactMessage(const std::string& proto_type);

// The first row whose artifact type `artifact` is (by its C++ type, without
// protobuf's descriptors), or nullptr for a type no stage writes.
const StageDefinition* StageWritingType(const google::protobuf::Message& artifact);

// The summary of an artifact of any stage, chosen by its type.
std::string SummarizeArtifact(const google::protobuf::Message& artifact);

}  // namespace areagraph
