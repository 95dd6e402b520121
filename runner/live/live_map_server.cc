#include "runner/live/live_map_server.h"

#include <climits>
#include <cmath>
#include <memory>
#include <sstream>
#include <utility>

#include "runner/live/lcm_connection.h"
#include "runner/live/lcm_conversion.h"
#include "stages/common/stage.h"
#include "stages/pipeline/map_pipeline.h"
#include "store/digest.h"
#include "store/error.h"

namespace areagraph {
namespace {

// Bounds one Serve call's intake when grids arrive faster than it reads them.
constexpr int kMaxMessagesPerServe = 1000;

// The stage that runs after `stage`, for naming where a map failed.
std::string StageAfter(const std::string& stage) {
  for (size_t i = 0; i + 1 < std::size(kAllStages); ++i) {
    if (stage == kAllStages[i].name) return kAllStages[i + 1].name;
  }
  return "publish";
}

std::string LiveSourcePath() { return std::string("LCM channel ") + kGridMapChannel; }

}  // namespace

std::string LiveGridDigest(const proto::GridMap& grid) {
  Sha256 digest;
  digest.Update("areagraph_lcm.grid_map_t\n");
  digest.Update(grid.frame().SerializeAsString());
  digest.Update(grid.cells());
  return digest.FinishHex();
}

LiveMapServer::LiveMapServer(ArtifactStore& store, AreaGraphPublisher& publisher,
                             proto::PipelineOptions options, std::ostream& out, std::ostream& log)
    : store_(store), publisher_(publisher), options_(std::move(options)), out_(out), log_(log) {
  subscription_ =
      publisher_.connection().subscribe(kGridMapChannel, &LiveMapServer::OnGridMessage, this);
  StartReceiving(publisher_.connection(), publisher_.url());
}

LiveMapServer::~LiveMapServer() { publisher_.connection().unsubscribe(subscription_); }

int LiveMapServer::Serve(int timeout_ms) {
  lcm::LCM& lcm = publisher_.connection();
  if (HandleOneMessage(lcm, timeout_ms, publisher_.url())) {
    for (int i = 1; i < kMaxMessagesPerServe && HandleOneMessage(lcm, 0, publisher_.url()); ++i) {
    }
  }
  int handled = 0;
  while (!pending_.empty()) {
    auto next = pending_.begin();
    const std::string map_name = next->first;
    proto::GridMap grid = std::move(next->second);
    pending_.erase(next);
    HandleMap(map_name, std::move(grid));
    ++handled;
  }
  return handled;
}

void LiveMapServer::OnGridMessage(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
  try {
    if (buffer->data_size > static_cast<uint32_t>(INT_MAX)) throw InputError("message too big");
    const areagraph_lcm::grid_map_t message =
        DecodeGridMapMessage(buffer->data, static_cast<int>(buffer->data_size));
    proto::GridMap grid = GridMapFromLcm(message, options_.import().max_pixels());
    if (pending_.count(message.name) > 0) {
      log_ << "ag-live: map '" << message.name
           << "': a newer grid arrived before this one was handled; skipping the older one\n";
    }
    pending_[message.name] = std::move(grid);
  } catch (const std::exception& error) {
    ++messages_rejected_;
    log_ << "ag-live: skipped a malformed message on " << channel << " (" << buffer->data_size
         << " bytes): " << error.what() << "\n";
  }
  log_.flush();
}

void LiveMapServer::HandleMap(const std::string& map_name, proto::GridMap grid) {
  const std::string digest = LiveGridDigest(grid);
  grid.set_source_path(LiveSourcePath());
  grid.set_source_digest(digest);
  StageInputs inputs;
  inputs.digests = {digest};
  inputs.source_path = grid.source_path();
  inputs.source_digest = digest;

  std::string failing_stage = kImportStage.name;
  int stages = 0, hits = 0;
  double compute_ms = 0;
  const auto count = [&](const StageInfo& stage, const StageRun& run) {
    failing_stage = StageAfter(stage.name);
    ++stages;
    hits += run.cache_hit ? 1 : 0;
    compute_ms += run.elapsed_ms;
  };
  try {
    count(kImportStage, RunCachedStage(store_, map_name, kImportStage, options_.import(), inputs,
                                       [&grid] { return std::make_unique<proto::GridMap>(grid); }));
    RunMapPipeline(store_, map_name, options_, /*force=*/false, count);
    std::string key;
    const auto graph = ReadHeadArtifact<proto::AreaGraph>(store_, map_name, kMergeStage, &key);
    publisher_.Publish(map_name, key, graph);
    store_.ClearFailure(map_name);

    std::ostringstream line;
    line << map_name << ": " << graph.areas_size() << " areas, " << graph.passages_size()
         << " passages, key " << key.substr(0, 12) << ", ";
    if (hits == stages) {
      line << "cached";
    } else {
      line << "computed " << (stages - hits) << " of " << stages << " stages in "
           << std::lround(compute_ms) << " ms";
    }
    out_ << line.str() << std::endl;
  } catch (const std::exception& error) {
    ++maps_failed_;
    log_ << "ag-live: map '" << map_name << "' failed in " << failing_stage << ": " << error.what()
         << "; still serving" << std::endl;
    try {
      store_.RecordFailure({map_name, failing_stage, error.what(), LiveSourcePath(), ""});
    } catch (const std::exception& store_error) {
      log_ << "ag-live: cannot record the failure: " << store_error.what() << std::endl;
    }
  }
  ++maps_handled_;
}

}  // namespace areagraph
