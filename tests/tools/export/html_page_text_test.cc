// Filling the page templates.
#include "tools/export/html_page_text.h"

#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>

#include "tools/export/markup_escape.h"
#include "tools/export/viewer_page.pb.h"

namespace areagraph {
namespace {

TEST(FillTemplate, FilledTextIsNeverSearchedAgain) {
  EXPECT_EQ(FillTemplate("<a>{{X}}</a><b>{{Y}}</b>", {{"{{Y}}", "y"}, {"{{X}}", "{{Y}}"}}),
            "<a>{{Y}}</a><b>y</b>");
  EXPECT_THROW(FillTemplate("no placeholder", {{"{{X}}", "x"}}), std::exception);
}

TEST(MarkupEscaped, EscapesMarkupCharacters) {
  EXPECT_EQ(MarkupEscaped("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&apos;");
}

TEST(ScriptJson, NoTextCanCloseTheScriptElementAndTheJsonReadsBack) {
  viewer::Page page;
  page.set_map_name("</script><!-- map");
  const std::string json = ScriptJson(page);
  EXPECT_EQ(json.find('<'), std::string::npos);
  viewer::Page parsed;
  ASSERT_TRUE(google::protobuf::util::JsonStringToMessage(json, &parsed).ok());
  EXPECT_EQ(parsed.map_name(), "</script><!-- map");
}

}  // namespace
}  // namespace areagraph
