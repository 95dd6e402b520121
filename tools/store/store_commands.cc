#include "tools/store/store_commands.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "common/error.h"
#include "common/text.h"
#include "stages/pipeline/stage_table.h"
#include "store/artifact_store.h"
#include "store/collection_index.h"
#include "store/store_maintenance.h"
#include "tools/inspect/failure_report.h"
#include "tools/store/collection_commands.h"
#include "tools/store/new_store_file.h"
#include "tools/store/store_text.h"

namespace areagraph {
namespace {

// Refuses a store that does not exist yet, with the store's own message:
// gc and verify must never create one.
void CheckStoreExists(const std::string& path) { OpenArtifactStore(path, StoreMode::kReadOnly); }

// "verifying 1200/5000 artifacts" on stderr, redrawn in place. Only stores
// that take a while show it, so small ones print nothing extra.
class ProgressLine {
 public:
  void Update(int64_t done, int64_t total) {
    const auto now = std::chrono::steady_clock::now();
    if (now - start_ < std::chrono::milliseconds(500)) return;
    if (shown_ && now - last_ < std::chrono::milliseconds(100) && done < total) return;
    std::fprintf(stderr, "\rverifying %lld/%lld artifacts (%lld%%)", static_cast<long long>(done),
                 static_cast<long long>(total), static_cast<long long>(100 * done / total));
    std::fflush(stderr);
    shown_ = true;
    last_ = now;
  }
  ~ProgressLine() {
    if (shown_) std::fputs("\r\033[K", stderr);  // clear the line for the report
  }

 private:
  const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last_;
  bool shown_ = false;
};

std::string OrDash(const std::string& text) { return text.empty() ? "-" : text; }

void MergeInto(const std::string& output, const std::vector<std::string>& inputs,
               std::ostream& out) {
  const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(output);
  for (const std::string& input : inputs) {
    const MaintenanceCounts added = store->MergeFrom(input);
    out << input << ": added " << Plural(added.maps, "map") << ", "
        << Plural(added.artifacts, "artifact") << " (" << FormatBytes(added.payload_bytes)
        << " of payload), " << Plural(added.failures, "failure") << "\n";
  }
}

}  // namespace

int MergeStores(const std::string& output, const std::vector<std::string>& named,
                std::ostream& out) {
  const std::vector<std::string> inputs = ExpandCollectionIndexes(named);
  for (const std::string& input : inputs) OpenArtifactStore(input, StoreMode::kReadOnly);
  if (NothingAt(output)) {
    CreateStoreFile(output,
                    [&](const std::string& temporary) { MergeInto(temporary, inputs, out); });
  } else {
    MergeInto(output, inputs, out);
  }
  out << "merged " << Plural(static_cast<int64_t>(inputs.size()), "store") << " into " << output
      << "\n";
  return 0;
}

int BackupStore(const std::string& store_path, const std::string& output, std::ostream& out) {
  const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(store_path, StoreMode::kReadOnly);
  CreateStoreFile(output, [&](const std::string& temporary) { store->BackupTo(temporary); });
  out << "backed up " << store_path << " to " << output << " ("
      << FormatBytes(StoreFileBytes(output)) << ")\n";
  return 0;
}

int CollectStoreGarbage(const std::string& store_path, bool keep_final, bool vacuum,
                        std::ostream& out) {
  CheckStoreExists(store_path);
  if (IsCollectionIndex(store_path)) {
    return CollectCollectionGarbage(
        store_path, keep_final ? CollectionScope::kFinal : CollectionScope::kAll, vacuum, out);
  }
  if (keep_final) {
    KeepFinalArtifacts(store_path, out);
  } else {
    out << RemovedText(OpenArtifactStore(store_path)->CollectGarbage()) << "\n";
  }
  if (vacuum) VacuumAndReport(store_path, store_path, out);
  return 0;
}

int VerifyStore(const std::string& store_path, bool progress, bool quick, bool shallow,
                std::ostream& out) {
  const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(store_path, StoreMode::kReadOnly);
  const bool collection = IsCollectionIndex(store_path);
  if (shallow && !collection) throw OptionsError("--shallow goes with a collection index");
  int64_t checked = 0;
  std::vector<VerifyProblem> problems;
  {
    ProgressLine line;
    const auto count = [&](int64_t done, int64_t total) {
      checked = done;
      if (progress) line.Update(done, total);
    };
    const StructureCheck structure = quick ? StructureCheck::kQuick : StructureCheck::kFull;
    problems = collection ? VerifyCollectionIndex(
                                store_path, FileInputStageNames(), count, structure,
                                shallow ? ShardCheck::kIndexedRowsOnly : ShardCheck::kFull)
                          : store->Verify(FileInputStageNames(), count, structure);
  }
  for (const VerifyProblem& problem : problems) {
    out << OrDash(problem.map_name) << " " << OrDash(problem.stage) << " "
        << OrDash(ShortKey(problem.cache_key)) << ": " << OneLine(problem.problem) << "\n";
  }
  out << "checked " << Plural(checked, "artifact") << ": "
      << (problems.empty() ? "no problems"
                           : Plural(static_cast<int64_t>(problems.size()), "problem"))
      << "\n";
  return problems.empty() ? 0 : 1;
}

int ListStoreFailures(const std::string& store_path, bool json, std::ostream& out) {
  const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(store_path, StoreMode::kReadOnly);
  if (json) {
    PrintFailuresJson(store->ReadFailures(), out);
  } else {
    PrintFailureList(store->ReadFailures(), out);
  }
  return 0;
}

}  // namespace areagraph
