#pragma once

#include <map>
#include <string>
#include <vector>

#include "tests/support/test_support.h"

namespace areagraph::testing {

// The one-node Slurm cluster of tools/slurm-local.sh, started for a test and
// stopped when this object goes (and, through the script's watcher, when the
// test process dies without running its destructors).
class LocalSlurmCluster {
 public:
  // Starts the daemons with their files under `dir`. When that fails,
  // running() is false and problem() says why.
  explicit LocalSlurmCluster(const std::string& dir);
  ~LocalSlurmCluster();
  LocalSlurmCluster(const LocalSlurmCluster&) = delete;
  LocalSlurmCluster& operator=(const LocalSlurmCluster&) = delete;

  bool running() const { return running_; }
  // The daemons cannot run here (not installed, or one did not come up), as
  // opposed to a fault of the script or its use.
  bool unavailable() const { return unavailable_; }
  const std::string& problem() const { return problem_; }

  // Runs `argv` in `cwd` with a clean environment: this cluster's SLURM_CONF,
  // the build's executables first on PATH, plus `env` ("NAME=value").
  CommandResult Run(const std::vector<std::string>& argv, const std::string& cwd,
                    const std::vector<std::string>& env = {}) const;

  // State of each job or array task that `job` names ("12", "12_3"), by id
  // as squeue prints it ("12_3"), with squeue's reason after a space.
  std::map<std::string, std::string> States(const std::string& job) const;

  // Polls squeue until every job or task of `jobs` has ended (COMPLETED,
  // FAILED, CANCELLED, ...); false after `timeout_s`.
  bool WaitUntilEnded(const std::vector<std::string>& jobs, double timeout_s) const;

  // Polls until job `job` is in `state` ("PENDING DependencyNeverSatisfied")
  // or `timeout_s` passed; returns the last state seen.
  std::string WaitForState(const std::string& job, const std::string& state,
                           double timeout_s) const;

 private:
  std::string dir_;
  bool running_ = false;
  bool unavailable_ = false;
  std::string problem_;
};

// Array job and collection job ids from the last line of slurm-submit.sh
// ("shards <id> index <id>", or "merge" for the merge step); empty strings
// when the line is not there.
struct SubmittedCollection {
  std::string shards;
  std::string step;        // "index" or "merge"
  std::string collection;  // the job of that step
};
SubmittedCollection ParseSubmitted(const std::string& output);

}  // namespace areagraph::testing
