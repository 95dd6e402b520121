#include "tests/support/headless_chromium.h"

#include <filesystem>
#include <sstream>
#include <vector>

#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

std::vector<std::string> ChromiumCommand(const std::string& profile,
                                         const std::vector<std::string>& extra) {
  std::vector<std::string> argv;
  if (HeadlessChromium::Offline()) argv = {"unshare", "-n"};
  // A hung browser must not hang the suite.
  argv.insert(argv.end(),
              {"timeout", "120", "chromium", "--headless", "--no-sandbox", "--disable-gpu",
               "--disable-quic", "--no-first-run", "--disable-background-networking",
               "--disable-component-update", "--disable-sync", "--disable-default-apps",
               "--mute-audio", "--enable-logging=stderr", "--user-data-dir=" + profile});
  argv.insert(argv.end(), extra.begin(), extra.end());
  return argv;
}

// The lines of chromium's log that carry the page's console messages.
std::string ConsoleLines(const std::string& log) {
  std::istringstream in(log);
  std::string lines;
  for (std::string line; std::getline(in, line);) {
    if (line.find(":CONSOLE") != std::string::npos) lines += line + "\n";
  }
  return lines;
}

}  // namespace

bool HeadlessChromium::Offline() {
  static const bool offline = RunProgram({"unshare", "-n", "true"}).exit_code == 0;
  return offline;
}

const std::string& HeadlessChromium::NotInstalled() {
  static const std::string reason =
      RunProgram({"sh", "-c", "command -v chromium"}).exit_code == 0
          ? ""
          : "chromium is not installed (tools/install-deps.sh installs it)";
  return reason;
}

const std::string& HeadlessChromium::Unavailable() {
  static const std::string reason = [] {
    if (!NotInstalled().empty()) return NotInstalled();
    const PageLoad blank = DumpDom("data:text/html,<p>ok</p>");
    if (blank.exit_code != 0 || blank.dom.find("<p>ok</p>") == std::string::npos) {
      return "chromium cannot start here (exit " + std::to_string(blank.exit_code) + ")";
    }
    return std::string();
  }();
  return reason;
}

HeadlessChromium::PageLoad HeadlessChromium::DumpDom(const std::string& url, int settle_ms) {
  TempDir profile;
  std::vector<std::string> flags = {"--dump-dom", url};
  if (settle_ms > 0)
    flags.insert(flags.begin(), "--virtual-time-budget=" + std::to_string(settle_ms));
  const CommandResult run = RunProgram(ChromiumCommand(profile.path(), flags));
  PageLoad load;
  load.exit_code = run.exit_code;
  load.dom = run.out;
  load.console = ConsoleLines(run.err);
  return load;
}

bool HeadlessChromium::Screenshot(const std::string& url, const std::string& png_path, int width,
                                  int height) {
  TempDir profile;
  std::filesystem::remove(png_path);
  const CommandResult run = RunProgram(ChromiumCommand(
      profile.path(),
      {"--screenshot=" + png_path, "--hide-scrollbars",
       "--window-size=" + std::to_string(width) + "," + std::to_string(height), url}));
  return run.exit_code == 0 && std::filesystem::exists(png_path);
}

std::string FileUrl(const std::string& path) {
  return "file://" + std::filesystem::absolute(path).string();
}

}  // namespace areagraph::testing
