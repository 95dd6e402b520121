#pragma once

#include <string>

namespace areagraph {

// `text` with &, <, >, " and ' written as entities (&apos; is XML's and
// HTML5's), fit for element content and quoted attributes of osmAG XML and
// of the HTML pages.
std::string MarkupEscaped(const std::string& text);

}  // namespace areagraph
