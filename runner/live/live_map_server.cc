#include "runner/live/live_map_server.h"

#include <climits>
#include <cmath>
#include <memory>
#include <sstream>
#include <utility>

#include "common/error.h"
#include "common/text.h"
#include "runner/common/map_run.h"
#include "runner/live/lcm_connection.h"
#include "runner/live/lcm_conversion.h"
#include "stages/match/area_graph_diff.h"
#include "store/digest.h"

namespace areagraph {
namespace {

// Bounds one Serve call's intake when grids arrive faster than it reads them.
constexpr int kMaxMessagesPerServe = 1000;

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
    : store_(store),
      failures_(store),
      publisher_(publisher),
      options_(std::move(options)),
      out_(out),
      log_(log) {
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
    PendingGrid grid = std::move(next->second);
    pending_.erase(next);
    HandleMap(map_name, std::move(grid));
    ++handled;
  }
  return handled;
}

void LiveMapServer::OnGridMessage(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
  const auto received = std::chrono::steady_clock::now();
  try {
    if (buffer->data_size > static_cast<uint32_t>(INT_MAX)) throw InputError("message too big");
    const areagraph_lcm::grid_map_t message =
        DecodeGridMapMessage(buffer->data, static_cast<int>(buffer->data_size));
    proto::GridMap grid = GridMapFromLcm(message, options_.import().max_pixels());
    if (pending_.count(message.name) > 0) {
      log_ << "ag-live: map '" << message.name
           << "': a newer grid arrived before this one was handled; skipping the older one\n";
    }
    pending_[message.name] = PendingGrid{std::move(grid), message.utime, received};
  } catch (const std::exception& error) {
    ++messages_rejected_;
    log_ << "ag-live: skipped a malformed message on " << channel << " (" << buffer->data_size
         << " bytes): " << error.what() << "\n";
  }
  log_.flush();
}

void LiveMapServer::PublishGraph(const std::string& map_name, const std::string& key,
                                 const proto::AreaGraph& graph, int64_t map_utime) {
  const auto last = last_published_.find(map_name);
  const bool repeat = last != last_published_.end() && last->second == key;
  const std::string& predecessor = graph.version().predecessor_key();
  // The diff goes first, so that a subscriber that stops after the graph has it.
  if (publish_diffs_ && !repeat && !predecessor.empty()) {
    try {
      const auto before = ReadArtifactAs<proto::AreaGraph>(store_, map_name, predecessor);
      publisher_.PublishDiff(map_name, key, DiffAreaGraphs(before, graph), graph, map_utime);
    } catch (const std::exception& error) {
      // E.g. gc dropped the previous version: the whole graph still goes out.
      log_ << "ag-live: map '" << map_name << "': no diff sent: " << error.what() << std::endl;
    }
  }
  publisher_.Publish(map_name, key, graph, map_utime);
  last_published_[map_name] = key;
}

void LiveMapServer::HandleMap(const std::string& map_name, PendingGrid pending) {
  proto::GridMap& grid = pending.grid;
  const std::string digest = LiveGridDigest(grid);
  grid.set_source_path(LiveSourcePath());
  grid.set_source_digest(digest);
  MapImport map_import;
  map_import.read_inputs = [&] {
    StageInputs inputs;
    inputs.digests = {digest};
    inputs.source_path = grid.source_path();
    inputs.source_digest = digest;
    return inputs;
  };
  map_import.decode = [&grid] { return std::make_unique<proto::GridMap>(grid); };
  MapRunSettings settings;
  settings.publish_unchanged = true;  // every grid received gets its graph
  std::string key;
  int64_t version = 0;
  const MapOutcome outcome = RunOneMap(
      store_, failures_, map_name, LiveSourcePath(), map_import, options_, settings,
      PipelineObserver{},
      [&](const std::string& name, const std::string& graph_key, const proto::AreaGraph& graph) {
        key = graph_key;
        version = graph.version().number();
        PublishGraph(name, graph_key, graph, pending.utime);
      });
  const double latency_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - pending.received)
          .count();
  ++maps_handled_;
  if (!outcome.ok) {
    ++maps_failed_;
    log_ << "ag-live: map '" << map_name << "' failed"
         << (outcome.failed_step.empty() ? "" : " in " + outcome.failed_step) << ": "
         << outcome.error << "; still serving" << std::endl;
    if (!outcome.failure_recorded) log_ << "ag-live: cannot record the failure" << std::endl;
    return;
  }
  std::ostringstream line;
  line << map_name << ": " << outcome.areas << " areas, " << outcome.passages << " passages, key "
       << ShortKey(key) << ", version " << version << ", ";
  if (outcome.fully_cached) {
    line << "cached";
  } else {
    line << "computed " << (outcome.stages_run - outcome.cache_hits) << " of " << outcome.stages_run
         << " stages in " << std::lround(outcome.compute_ms) << " ms";
  }
  line << ", published " << std::lround(latency_ms) << " ms after receipt";
  out_ << line.str() << std::endl;
}

}  // namespace areagraph
