#include "runner/run/process_pool.h"

#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <exception>

#include "common/error.h"

namespace areagraph {

// Frames from a worker: a kind byte, a 4-byte length, then the payload.
constexpr char kEventFrame = 'E';      // a message from Work
constexpr char kTaskDoneFrame = 'D';   // the task ended normally
constexpr char kTaskThrewFrame = 'X';  // Work threw; the payload is what()
constexpr size_t kFrameHeader = 5;

// Task numbers that end a worker: the plain end, and the end of the worker
// that ends last (OnWorkerEnd's `last`).
constexpr int kEnd = -1;
constexpr int kEndLast = -2;

struct ProcessPool::Worker {
  pid_t pid = -1;
  int task_fd = -1;   // parent writes task numbers; closed once told to end
  int event_fd = -1;  // parent reads event lines
  int task = -1;      // the task in progress, or -1 when idle
  std::string buffer;
};

namespace {

bool WriteAll(int fd, const char* data, size_t size) {
  while (size > 0) {
    const ssize_t written = write(fd, data, size);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) return false;
    data += written;
    size -= static_cast<size_t>(written);
  }
  return true;
}

bool ReadAll(int fd, char* data, size_t size) {
  while (size > 0) {
    const ssize_t got = read(fd, data, size);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return false;
    data += got;
    size -= static_cast<size_t>(got);
  }
  return true;
}

std::string DescribeExit(int status) {
  if (WIFSIGNALED(status)) {
    const int signal = WTERMSIG(status);
    return "the worker process died of signal " + std::to_string(signal) + " (" +
           strsignal(signal) + ")";
  }
  return "the worker process exited with status " + std::to_string(WEXITSTATUS(status));
}

}  // namespace

void EventWriter::Write(const std::string& message) { WriteFrame(kEventFrame, message); }

void EventWriter::WriteFrame(char kind, const std::string& payload) {
  const uint32_t size = static_cast<uint32_t>(payload.size());
  std::string frame(1, kind);
  frame.append(reinterpret_cast<const char*>(&size), sizeof(size));
  frame += payload;
  if (!WriteAll(fd_, frame.data(), frame.size())) _exit(3);  // the parent is gone
}

ProcessPool::ProcessPool(int jobs, Work work, OnEvent on_event, OnTaskEnd on_task_end,
                         std::function<void()> on_tick, OnWorkerEnd on_worker_end)
    : jobs_(jobs),
      work_(std::move(work)),
      on_event_(std::move(on_event)),
      on_task_end_(std::move(on_task_end)),
      on_tick_(std::move(on_tick)),
      on_worker_end_(std::move(on_worker_end)) {}

void ProcessPool::WorkerLoop(int task_fd, int event_fd) {
  EventWriter events(event_fd);
  int task = 0;
  while (ReadAll(task_fd, reinterpret_cast<char*>(&task), sizeof(task))) {
    if (task < 0) {
      try {
        if (on_worker_end_) on_worker_end_(task == kEndLast);
      } catch (...) {
        // No task to report it on; the caller checks what the hook did.
      }
      break;
    }
    try {
      work_(task, events);
      events.WriteFrame(kTaskDoneFrame, "");
    } catch (const std::exception& error) {
      events.WriteFrame(kTaskThrewFrame, error.what());
    } catch (...) {
      // Anything else must not unwind into the code that forked this worker.
      events.WriteFrame(kTaskThrewFrame,
                        "the task threw an exception that is not a std::exception");
    }
  }
  std::fflush(nullptr);
  _exit(0);  // no destructors or atexit handlers of the parent's objects
}

void ProcessPool::StartWorker(Worker& worker, const std::vector<Worker>& workers) {
  int task_pipe[2], event_pipe[2];
  if (pipe(task_pipe) != 0 || pipe(event_pipe) != 0) {
    throw Error(std::string("cannot create a pipe for a worker: ") + std::strerror(errno));
  }
  const pid_t parent = getpid();
  std::fflush(nullptr);  // nothing buffered is written twice
  const pid_t pid = fork();
  if (pid < 0) throw Error(std::string("cannot fork a worker: ") + std::strerror(errno));
  if (pid == 0) {
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(4);  // the parent died before prctl
    signal(SIGPIPE, SIG_DFL);
    signal(SIGINT, SIG_IGN);   // the runner stops its workers itself
    signal(SIGTERM, SIG_DFL);  // not the runner's handler
    for (const Worker& other : workers) {
      if (other.task_fd >= 0) close(other.task_fd);
      if (other.event_fd >= 0) close(other.event_fd);
    }
    close(task_pipe[1]);
    close(event_pipe[0]);
    WorkerLoop(task_pipe[0], event_pipe[1]);
  }
  close(task_pipe[0]);
  close(event_pipe[1]);
  worker.pid = pid;
  worker.task_fd = task_pipe[1];
  worker.event_fd = event_pipe[0];
  worker.task = -1;
  worker.buffer.clear();
}

namespace {

// A failed write means the worker died; its closed event pipe reports that.
void SendTask(int fd, int task) {
  WriteAll(fd, reinterpret_cast<const char*>(&task), sizeof(task));
}

// `end` is kEnd or kEndLast; the worker then gets nothing more.
void SendEnd(int& task_fd, int end) {
  SendTask(task_fd, end);
  close(task_fd);
  task_fd = -1;
}

}  // namespace

void ProcessPool::Assign(Worker& worker) {
  worker.task = -1;  // idle when no task is left: EndIdleWorkers ends it
  if (next_task_ >= task_count_) return;
  worker.task = next_task_++;
  SendTask(worker.task_fd, worker.task);
}

void ProcessPool::EndIdleWorkers(std::vector<Worker>& workers) {
  if (next_task_ < task_count_) return;
  int alive = 0;
  bool busy = false;
  for (const Worker& worker : workers) {
    if (worker.pid < 0) continue;
    ++alive;
    busy = busy || worker.task >= 0;
  }
  // With no task running, one idle worker waits until it is the only one
  // left and then ends as the last; every other idle worker ends now.
  Worker* last = nullptr;
  for (Worker& worker : workers) {
    if (worker.pid < 0 || worker.task >= 0 || worker.task_fd < 0) continue;
    if (!busy && last == nullptr) {
      last = &worker;
      continue;
    }
    SendEnd(worker.task_fd, kEnd);
  }
  if (last != nullptr && alive == 1) SendEnd(last->task_fd, kEndLast);
}

bool ProcessPool::ReadEvents(Worker& worker) {
  char chunk[4096];
  const ssize_t got = read(worker.event_fd, chunk, sizeof(chunk));
  if (got < 0 && errno == EINTR) return true;
  if (got <= 0) return false;
  worker.buffer.append(chunk, static_cast<size_t>(got));
  while (worker.buffer.size() >= kFrameHeader) {
    uint32_t size = 0;
    std::memcpy(&size, worker.buffer.data() + 1, sizeof(size));
    if (worker.buffer.size() < kFrameHeader + size) break;
    const char kind = worker.buffer[0];
    const std::string payload = worker.buffer.substr(kFrameHeader, size);
    worker.buffer.erase(0, kFrameHeader + size);
    if (worker.task < 0) continue;
    if (kind == kEventFrame) {
      on_event_(worker.task, payload);
    } else {
      on_task_end_(worker.task, kind == kTaskThrewFrame ? payload : "");
      Assign(worker);
    }
  }
  return true;
}

void ProcessPool::Reap(Worker& worker) {
  int status = 0;
  while (waitpid(worker.pid, &status, 0) < 0 && errno == EINTR) {
  }
  close(worker.event_fd);
  if (worker.task_fd >= 0) close(worker.task_fd);
  const int task = worker.task;
  worker = Worker{};
  if (task >= 0) on_task_end_(task, DescribeExit(status));
}

void ProcessPool::KillWorkers(std::vector<Worker>& workers) {
  for (Worker& worker : workers) {
    if (worker.pid < 0) continue;
    kill(worker.pid, SIGKILL);
    worker.task = -1;  // not run: nothing to report
    Reap(worker);
  }
}

void ProcessPool::Run(int task_count) {
  signal(SIGPIPE, SIG_IGN);  // a dead worker's pipe must not kill the runner
  task_count_ = task_count;
  next_task_ = 0;
  stopped_ = false;
  std::vector<Worker> workers(static_cast<size_t>(std::max(1, std::min(jobs_, task_count))));
  if (task_count == 0) return;
  for (Worker& worker : workers) {
    StartWorker(worker, workers);
    Assign(worker);
  }
  while (true) {
    if (stop_ != nullptr && *stop_ != 0) {
      KillWorkers(workers);
      stopped_ = true;
      return;
    }
    std::vector<pollfd> fds;
    std::vector<Worker*> owners;
    for (Worker& worker : workers) {
      if (worker.pid < 0) continue;
      fds.push_back({worker.event_fd, POLLIN, 0});
      owners.push_back(&worker);
    }
    if (fds.empty()) return;
    const int ready = poll(fds.data(), fds.size(), 200);
    if (on_tick_) on_tick_();
    if (ready <= 0) continue;
    for (size_t i = 0; i < fds.size(); ++i) {
      if (fds[i].revents == 0) continue;
      Worker& worker = *owners[i];
      if (ReadEvents(worker)) continue;
      Reap(worker);
      if (next_task_ < task_count_) {
        StartWorker(worker, workers);
        Assign(worker);
      }
    }
    EndIdleWorkers(workers);
  }
}

}  // namespace areagraph
