// ag-bench-exec: the CPU time of one command's own process, run again and
// again (tools/bench-speed.sh's render table times ag-render with it).
//
// Runs COMMAND --repeat times, one process after another, each started with
// posix_spawn (glibc's runs the child in the launcher's memory until its
// exec, so no page of the launcher is copied or faulted for it) and reaped
// with wait4, whose resource usage is that child's alone: its CPU time from
// the exec to its exit, start-up included. A launcher that forks, as a bash
// loop under /usr/bin/time does, is charged the fork's page-table copy and
// copy-on-write faults besides, several ms per process on a loaded machine
// (docs/performance.md, "How to benchmark"). Prints the medians of
// CPU (user + system), user, system and wall milliseconds and of the minor
// page faults, and the mean CPU milliseconds. The command's output is
// discarded. A benchmark: it checks nothing but the command's exit status.
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <numeric>
#include <string>
#include <vector>

#include "common/error.h"
#include "stages/common/command_line.h"
#include "tools/bench/median_timer.h"

extern char** environ;

using namespace areagraph;

namespace {

double Ms(const timeval& time) {
  return static_cast<double>(time.tv_sec) * 1e3 + static_cast<double>(time.tv_usec) / 1e3;
}

struct ChildUsage {
  double user_ms = 0, system_ms = 0, wall_ms = 0, minor_faults = 0;
};

// Runs `command` once with its standard output and error on /dev/null.
ChildUsage RunOnce(const std::vector<std::string>& command, int run) {
  std::vector<char*> argv;
  for (const std::string& arg : command) argv.push_back(const_cast<char*>(arg.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid = 0;
  ChildUsage usage;
  int status = 0;
  rusage own{};
  const auto start = std::chrono::steady_clock::now();
  int error = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  if (error == 0 && wait4(pid, &status, 0, &own) != pid) error = errno;
  usage.wall_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0) throw InputError("cannot run '" + command[0] + "': " + std::strerror(error));
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw InputError("'" + command[0] + "' failed on run " + std::to_string(run + 1) +
                     " (wait status " + std::to_string(status) + "); run it alone to see why");
  }
  usage.user_ms = Ms(own.ru_utime);
  usage.system_ms = Ms(own.ru_stime);
  usage.minor_faults = static_cast<double>(own.ru_minflt);
  return usage;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Median CPU milliseconds of a command's own process (start-up included), run "
      "--repeat times."};
  int repeat = 9;
  std::vector<std::string> command;
  app.add_option("--repeat", repeat, "runs of the command")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  app.add_option("command", command, "the command and its arguments (after --)")->required();
  return RunCommand("ag-bench-exec", app, argc, argv, [&] {
    std::vector<double> cpu, user, system, wall, faults;
    for (int run = 0; run < repeat; ++run) {
      const ChildUsage usage = RunOnce(command, run);
      cpu.push_back(usage.user_ms + usage.system_ms);
      user.push_back(usage.user_ms);
      system.push_back(usage.system_ms);
      wall.push_back(usage.wall_ms);
      faults.push_back(usage.minor_faults);
    }
    const double mean = std::accumulate(cpu.begin(), cpu.end(), 0.0) / repeat;
    std::printf(
        "cpu_ms %.2f user_ms %.2f sys_ms %.2f wall_ms %.2f minor_faults %.0f "
        "mean_cpu_ms %.2f runs %d\n",
        Median(cpu), Median(user), Median(system), Median(wall), Median(faults), mean, repeat);
    return 0;
  });
}
