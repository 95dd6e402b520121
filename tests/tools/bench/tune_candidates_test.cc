// tools/tune.sh chooses the constants by script; its --check ties
// tools/tune-candidates.txt to the code: every tunable constant that
// tools/count-tunables.sh lists has candidates, and each candidate's default
// is the value the code declares today.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "tests/support/test_support.h"

namespace areagraph::testing {
namespace {

CommandResult CheckCandidates(const std::string& file) {
  return RunProgram({"bash", SourcePath("tools/tune.sh"), "--check", "--build", BinDir() + "/..",
                     "--candidates", file});
}

TEST(TuneCandidates, EveryTunableConstantHasCandidatesWithItsDefault) {
  const CommandResult check = CheckCandidates(SourcePath("tools/tune-candidates.txt"));
  EXPECT_EQ(check.exit_code, 0) << check.err;
  EXPECT_NE(check.out.find(" candidates checked"), std::string::npos) << check.out;
}

// The first constant's line of the candidates file: "constant FILE NAME DEFAULT ...".
struct CandidateLine {
  size_t begin = std::string::npos;
  size_t end = std::string::npos;
  std::string file, name, default_value;
};

CandidateLine FirstConstant(const std::string& candidates) {
  CandidateLine line;
  line.begin = candidates.find("\nconstant ");
  if (line.begin == std::string::npos) return line;
  ++line.begin;
  line.end = candidates.find('\n', line.begin);
  std::istringstream fields(candidates.substr(line.begin, line.end - line.begin));
  std::string kind;
  fields >> kind >> line.file >> line.name >> line.default_value;
  return line;
}

TEST(TuneCandidates, RefusesADefaultTheCodeNoLongerHolds) {
  const std::string candidates = ReadFile(SourcePath("tools/tune-candidates.txt"));
  const CandidateLine line = FirstConstant(candidates);
  ASSERT_NE(line.begin, std::string::npos);
  std::string stale = candidates;
  stale.replace(line.begin, line.end - line.begin,
                "constant " + line.file + " " + line.name + " 12345 1 2");
  TempDir dir;
  WriteFile(dir.File("stale.txt"), stale);
  const CommandResult check = CheckCandidates(dir.File("stale.txt"));
  EXPECT_EQ(check.exit_code, 1);
  EXPECT_NE(check.err.find(line.name + " = " + line.default_value), std::string::npos) << check.err;
}

TEST(TuneCandidates, RefusesATunableConstantWithoutCandidates) {
  const std::string candidates = ReadFile(SourcePath("tools/tune-candidates.txt"));
  const CandidateLine line = FirstConstant(candidates);
  ASSERT_NE(line.begin, std::string::npos);
  std::string missing = candidates;
  missing.erase(line.begin, line.end + 1 - line.begin);
  TempDir dir;
  WriteFile(dir.File("missing.txt"), missing);
  const CommandResult check = CheckCandidates(dir.File("missing.txt"));
  EXPECT_EQ(check.exit_code, 1);
  // count-tunables names a Params field "Params::field"; the check names the field.
  const std::string field = line.name.substr(line.name.rfind(':') + 1);
  EXPECT_NE(check.err.find(line.file + ":" + field), std::string::npos) << check.err;
}

}  // namespace
}  // namespace areagraph::testing
