// The osmAG of real maps through JOSM's own validator (`josm validate`,
// Debian's josm, headless), which is what a user who opens the file sees:
// no warning and no error on areagraph/ lab_a, lab_e, sistD (lab_a's
// corridor loop has holes with passages on them; lab_e has outlines that
// come back within a centimetre of themselves) and bormann/ office_d.
// Skips with one line where JOSM cannot start or ../shared/data is absent.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

constexpr char kJosm[] = "/usr/bin/josm";

// The first string member `key` in a line of JOSM's GeoJSON.
std::string JsonField(const std::string& line, const std::string& key) {
  const std::string start = "\"" + key + "\":\"";
  const size_t at = line.find(start);
  if (at == std::string::npos) return "";
  const size_t from = at + start.size();
  return line.substr(from, line.find('"', from) - from);
}

// The first line of `log` that names an exception or error, for a skip.
std::string FirstProblem(const std::string& log) {
  std::istringstream lines(log);
  for (std::string line; std::getline(lines, line);) {
    if (line.find("Exception") != std::string::npos || line.find("Error") != std::string::npos ||
        line.find("not found") != std::string::npos) {
      return line;
    }
  }
  return "josm validate ended without validating anything";
}

TEST(JosmValidation, FindsNoWarningOrErrorOnFourRealMaps) {
  if (!HaveSharedData()) GTEST_SKIP() << "../shared/data is missing";
  if (!std::filesystem::exists(kJosm)) GTEST_SKIP() << kJosm << " is not installed";
  const TempDir dir;
  const std::vector<std::string> files = {"areagraph/input/lab_a.png", "areagraph/input/lab_e.png",
                                          "areagraph/input/sistD.png", "bormann/office_d.png"};
  std::vector<std::string> run = {"--store", dir.File("store.db"), "--jobs", "1"};
  for (const std::string& file : files) run.push_back(SharedDataPath(file));
  const CommandResult ran = RunTool("ag-run", run);
  ASSERT_EQ(ran.exit_code, 0) << ran.err;

  // One JOSM for all four files (its start costs more than a validation).
  // JOSM (and Java's font cache) keep their files in the test's folder, and
  // every request JOSM makes (it asks api.openstreetmap.org for the API's
  // limits) goes to a closed port on this host: the test sends nothing off
  // the machine.
  std::vector<std::string> validate = {
      "/usr/bin/env",
      "JAVA_OPTS=-Djosm.home=" + dir.File("josm") + " -Duser.home=" + dir.path() +
          " -Djava.awt.headless=true -Djava.net.useSystemProxies=false"
          " -Dhttp.proxyHost=127.0.0.1 -Dhttp.proxyPort=9"
          " -Dhttps.proxyHost=127.0.0.1 -Dhttps.proxyPort=9",
      kJosm, "validate"};
  std::vector<std::string> maps;
  for (const std::string& file : files) {
    const std::string map = std::filesystem::path(file).stem();
    maps.push_back(map);
    const CommandResult exported =
        RunTool("ag-export", {"--store", dir.File("store.db"), "--map", map, "--format", "osmag",
                              "--out", dir.File(map + ".osm")});
    ASSERT_EQ(exported.exit_code, 0) << exported.err;
    validate.insert(validate.end(),
                    {"--input", dir.File(map + ".osm"), "--output", dir.File(map + ".findings")});
  }
  const CommandResult validated = RunProgram(validate);
  const std::string log = validated.out + validated.err;
  // JOSM exits 0 even when it fails; it logs each file it validates.
  if (log.find("Validating ") == std::string::npos) {
    GTEST_SKIP() << "JOSM cannot start here: " << FirstProblem(log);
  }

  for (const std::string& map : maps) {
    const std::string findings_file = dir.File(map + ".findings");
    ASSERT_NE(log.find("saving output to " + findings_file + " completed"), std::string::npos)
        << map << ": JOSM did not finish validating it\n"
        << log;
    // One line per finding (none when there is none), each with its
    // severity: Errors, Warnings or Other. Other is information, such as "No
    // area style for multipolygon" (JOSM's map style draws no indoor=room)
    // and "Multipolygon rings share node" (rings that touch where a neck is
    // narrower than OSM's precision).
    std::istringstream findings(std::filesystem::exists(findings_file) ? ReadFile(findings_file)
                                                                       : "");
    std::string problems;
    int count = 0;
    for (std::string line; std::getline(findings, line);) {
      if (line.empty() || JsonField(line, "severity") == "Other") continue;
      problems += "\n  " + JsonField(line, "severity") + ": " + JsonField(line, "message");
      ++count;
    }
    EXPECT_EQ(count, 0) << map << ":" << problems;
  }
}

}  // namespace
}  // namespace areagraph::testing
