#include "tests/examples/cluster/local_slurm_cluster.h"

#include <unistd.h>

#include <chrono>
#include <sstream>
#include <thread>

namespace areagraph::testing {
namespace {

// Job states after which a job does nothing more (squeue's long names).
bool HasEnded(const std::string& state_and_reason) {
  const std::string state = state_and_reason.substr(0, state_and_reason.find(' '));
  for (const char* running : {"PENDING", "CONFIGURING", "RUNNING", "COMPLETING", "SUSPENDED",
                              "REQUEUED", "RESIZING", "SIGNALING", "STAGE_OUT", "STOPPED"}) {
    if (state == running) return false;
  }
  return true;
}

}  // namespace

LocalSlurmCluster::LocalSlurmCluster(const std::string& dir) : dir_(dir) {
  const CommandResult start = RunProgram({"bash", SourcePath("tools/slurm-local.sh"), "start", dir_,
                                          "--stop-with", std::to_string(getpid())});
  running_ = start.exit_code == 0;
  unavailable_ = start.exit_code == 77;  // the script's "cannot run here"
  if (!running_) {
    problem_ =
        "tools/slurm-local.sh start exited " + std::to_string(start.exit_code) + ": " + start.err;
  }
}

LocalSlurmCluster::~LocalSlurmCluster() {
  RunProgram({"bash", SourcePath("tools/slurm-local.sh"), "stop", dir_});
}

CommandResult LocalSlurmCluster::Run(const std::vector<std::string>& argv, const std::string& cwd,
                                     const std::vector<std::string>& env) const {
  std::vector<std::string> all = {"env",
                                  "-i",
                                  "--chdir=" + cwd,
                                  "PATH=" + std::string(AG_BIN_DIR) + ":/usr/bin:/bin",
                                  "HOME=" + cwd,
                                  "SLURM_CONF=" + dir_ + "/slurm.conf"};
  all.insert(all.end(), env.begin(), env.end());
  all.insert(all.end(), argv.begin(), argv.end());
  return RunProgram(all);
}

std::map<std::string, std::string> LocalSlurmCluster::States(const std::string& job) const {
  // -t all: ended jobs too (the controller keeps them for MinJobAge); -r: one
  // line per array task, also for tasks not yet started.
  const CommandResult squeue =
      Run({"squeue", "-h", "-r", "-t", "all", "-j", job, "-o", "%i %T %r"}, "/");
  std::map<std::string, std::string> states;
  std::istringstream lines(squeue.out);
  for (std::string line; std::getline(lines, line);) {
    const size_t space = line.find(' ');
    if (space != std::string::npos) states[line.substr(0, space)] = line.substr(space + 1);
  }
  return states;
}

bool LocalSlurmCluster::WaitUntilEnded(const std::vector<std::string>& jobs,
                                       double timeout_s) const {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < deadline) {
    bool ended = true;
    for (const std::string& job : jobs) {
      const auto states = States(job);
      if (states.empty()) ended = false;  // not visible yet, or squeue failed
      for (const auto& [id, state] : states) ended = ended && HasEnded(state);
    }
    if (ended) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  return false;
}

std::string LocalSlurmCluster::WaitForState(const std::string& job, const std::string& state,
                                            double timeout_s) const {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  std::string seen;
  while (std::chrono::steady_clock::now() < deadline) {
    const auto states = States(job);
    seen = states.count(job) != 0 ? states.at(job) : "(not in squeue)";
    if (seen == state) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  return seen;
}

SubmittedCollection ParseSubmitted(const std::string& output) {
  SubmittedCollection jobs;
  std::istringstream lines(output);
  std::string last;
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty()) last = line;
  }
  std::istringstream words(last);
  std::string shards_word;
  if (words >> shards_word >> jobs.shards >> jobs.step >> jobs.collection &&
      shards_word == "shards" && (jobs.step == "index" || jobs.step == "merge")) {
    return jobs;
  }
  return {};
}

}  // namespace areagraph::testing
