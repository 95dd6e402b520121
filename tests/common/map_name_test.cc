// CheckMapName: the one rule for map names, wherever they come from.
#include "common/map_name.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/error.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

std::string Problem(const std::string& name) {
  return testing::ErrorOf<InputError>([&] { CheckMapName(name); });
}

TEST(MapNameTest, NamesOfFilesAndFoldersAreAccepted) {
  for (const std::string& name :
       std::vector<std::string>{"lab_a", "w=1_25/lab_b", "Freiburg101_scan", "floor1/wing-a/room.2",
                                "büro", "a+b,c(1)", std::string(256, 'x')}) {
    EXPECT_EQ(Problem(name), "") << name;
  }
}

// The names, accepted by ag-import, ag-run and manifests while
// ag-live refused them.
TEST(MapNameTest, PathsOutsideBlanksAndControlCharactersAreRefused) {
  EXPECT_EQ(Problem(""), "map name is empty");
  EXPECT_EQ(Problem(std::string(257, 'x')), "map name has 257 bytes; at most 256 are allowed");
  EXPECT_EQ(Problem(".."), "map name '..' may not hold a '..' part");
  EXPECT_EQ(Problem("a/../b"), "map name 'a/../b' may not hold a '..' part");
  EXPECT_EQ(Problem("./a"), "map name './a' may not hold a '.' part");
  EXPECT_EQ(Problem("/abs"), "map name '/abs' may not start or end with '/'");
  EXPECT_EQ(Problem("a/"), "map name 'a/' may not start or end with '/'");
  EXPECT_EQ(Problem("a//b"), "map name 'a//b' holds an empty part ('//')");
  EXPECT_EQ(Problem("my map"), "map name 'my map' holds a blank");
  EXPECT_EQ(Problem("my\xC2\xA0map"), "map name 'my\xC2\xA0map' holds a blank");
  EXPECT_EQ(Problem("a\tb"), "map name 'a\\x09b' holds a control character (a tab or line break)");
  EXPECT_EQ(Problem("a\nb"), "map name 'a\\x0ab' holds a control character (a tab or line break)");
  EXPECT_EQ(Problem("a\xFF"), "map name 'a\xFF' is not UTF-8 text");
  EXPECT_EQ(Problem("a\xC0\xAF"), "map name 'a\xC0\xAF' is not UTF-8 text");  // overlong '/'
}

}  // namespace
}  // namespace areagraph
