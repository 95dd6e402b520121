#pragma once

#include <csignal>
#include <functional>
#include <string>
#include <vector>

namespace areagraph {

// How a worker reports on its task: each Write is one message of any bytes
// (the runner's are serialized WorkerEvent protos), framed by its length.
class EventWriter {
 public:
  explicit EventWriter(int fd) : fd_(fd) {}
  void Write(const std::string& message);

 private:
  friend class ProcessPool;
  // A frame of `kind` (see process_pool.cc) with `payload`.
  void WriteFrame(char kind, const std::string& payload);
  int fd_;
};

// Runs tasks 0..n-1 in worker processes forked from this one, so that a task
// that crashes (a segfault inside CGAL, an abort) takes down only its worker:
// the pool reports it and forks a replacement. Workers are forked from this
// process, so they share everything it built before Run (the task list, the
// options); the caller must not hold an SQLite connection across Run, since
// SQLite connections must not cross fork(). Workers die with the parent
// (PR_SET_PDEATHSIG), so killing the runner stops everything.
class ProcessPool {
 public:
  // Runs in a worker for each task it is given.
  using Work = std::function<void(int task, EventWriter& events)>;
  // Runs in the parent for each message a worker writes about `task`.
  using OnEvent = std::function<void(int task, const std::string& message)>;
  // Runs in the parent when `task` has ended: `crash` is empty when the
  // worker finished it, else what killed the worker or what Work threw.
  using OnTaskEnd = std::function<void(int task, const std::string& crash)>;
  // Runs in a worker when no task is left for it, before it exits. `last`
  // is true in the one worker that finished the last task, and only once
  // every other worker has exited (none does when that task crashed its
  // worker): work that all workers' results must be in, done once, by a
  // process that is still warm. What it throws is dropped.
  using OnWorkerEnd = std::function<void(bool last)>;

  ProcessPool(int jobs, Work work, OnEvent on_event, OnTaskEnd on_task_end,
              std::function<void()> on_tick = nullptr, OnWorkerEnd on_worker_end = nullptr);

  // Runs every task; returns when all have ended and all workers are gone.
  // Throws Error when a worker cannot be forked at all.
  void Run(int task_count);

  // Makes Run stop as soon as `*flag` is non-zero (a signal handler sets
  // it): the workers are killed (SIGKILL: their open transactions roll
  // back) and reaped without reporting their tasks, which count as not run.
  // Workers ignore SIGINT, which a terminal sends to all of them, so that
  // the runner alone decides.
  void StopWhen(const volatile std::sig_atomic_t* flag) { stop_ = flag; }
  // Whether the last Run stopped that way.
  bool stopped() const { return stopped_; }

 private:
  struct Worker;
  void StartWorker(Worker& worker, const std::vector<Worker>& workers);
  [[noreturn]] void WorkerLoop(int task_fd, int event_fd);
  void Assign(Worker& worker);
  // Tells the workers that have no task left to end (see OnWorkerEnd).
  void EndIdleWorkers(std::vector<Worker>& workers);
  bool ReadEvents(Worker& worker);
  void Reap(Worker& worker);
  void KillWorkers(std::vector<Worker>& workers);

  int jobs_;
  Work work_;
  OnEvent on_event_;
  OnTaskEnd on_task_end_;
  std::function<void()> on_tick_;
  OnWorkerEnd on_worker_end_;
  int next_task_ = 0;
  int task_count_ = 0;
  const volatile std::sig_atomic_t* stop_ = nullptr;
  bool stopped_ = false;
};

}  // namespace areagraph
