#include "runner/run/worker_events.h"

#include "runner/run/worker_event.pb.h"

namespace areagraph {

std::string StageStartedEvent(const StageInfo& stage) {
  proto::WorkerEvent event;
  event.mutable_stage_started()->set_stage(stage.name);
  return event.SerializeAsString();
}

std::string StageDoneEvent(const StageInfo& stage, const StageRun& run) {
  proto::WorkerEvent event;
  proto::WorkerEvent::StageDone* done = event.mutable_stage_done();
  done->set_stage(stage.name);
  done->set_cache_hit(run.cache_hit);
  done->set_elapsed_ms(run.elapsed_ms);
  return event.SerializeAsString();
}

std::string MapEndedEvent(const MapOutcome& outcome) {
  proto::WorkerEvent event;
  proto::WorkerEvent::MapEnded* ended = event.mutable_map_ended();
  ended->set_ok(outcome.ok);
  ended->set_failed_step(outcome.failed_step);
  ended->set_error(outcome.error);
  ended->set_areas(outcome.areas);
  ended->set_passages(outcome.passages);
  ended->set_fully_cached(outcome.fully_cached);
  ended->set_published(outcome.published);
  ended->set_failure_recorded(outcome.failure_recorded);
  return event.SerializeAsString();
}

void ApplyWorkerEvent(const std::string& bytes, int task, RunReport& report) {
  proto::WorkerEvent event;
  if (!event.ParseFromString(bytes)) return;
  switch (event.event_case()) {
    case proto::WorkerEvent::kStageStarted:
      report.StageStarted(task, event.stage_started().stage());
      break;
    case proto::WorkerEvent::kStageDone:
      report.StageDone(task, event.stage_done().stage(), event.stage_done().cache_hit(),
                       event.stage_done().elapsed_ms());
      break;
    case proto::WorkerEvent::kMapEnded: {
      const proto::WorkerEvent::MapEnded& ended = event.map_ended();
      MapOutcome outcome;
      outcome.ok = ended.ok();
      outcome.failed_step = ended.failed_step();
      outcome.error = ended.error();
      outcome.areas = ended.areas();
      outcome.passages = ended.passages();
      outcome.fully_cached = ended.fully_cached();
      outcome.published = ended.published();
      outcome.failure_recorded = ended.failure_recorded();
      report.MapEnded(task, outcome);
      break;
    }
    case proto::WorkerEvent::EVENT_NOT_SET:
      break;
  }
}

}  // namespace areagraph
