// OneLine: library messages that span lines become one line.
#include "common/text.h"

#include <gtest/gtest.h>

namespace areagraph {
namespace {

TEST(TextTest, OneLineJoinsLinesAndTrims) {
  EXPECT_EQ(OneLine("plain"), "plain");
  EXPECT_EQ(OneLine(""), "");
  EXPECT_EQ(OneLine("\n\n"), "");
  // An OpenCV exception's what(): a trailing line break.
  EXPECT_EQ(OneLine("OpenCV(4.6.0) alloc.cpp:73: error: (-4:Insufficient memory) Failed\n"),
            "OpenCV(4.6.0) alloc.cpp:73: error: (-4:Insufficient memory) Failed");
  // SQLite's b-tree findings, a line each.
  EXPECT_EQ(OneLine("*** in database main ***\nPage 4: btreeInitPage() returns error code 11\n"
                    "row 3 missing from index x"),
            "*** in database main ***; Page 4: btreeInitPage() returns error code 11; row 3 "
            "missing from index x");
  EXPECT_EQ(OneLine("  a  \r\n\r\n   b\tc "), "a; b c");
}

}  // namespace
}  // namespace areagraph
